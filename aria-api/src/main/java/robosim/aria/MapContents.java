package robosim.aria;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import robosim.map.Cairn;
import robosim.map.Coordinates;
import robosim.map.MapFile;
import robosim.map.MapHeader;

/** What one file gave, replaced whole so that a failed read leaves the map as it was. */
record MapContents(List<ArMapObject> objects, List<ArPose> points, List<ArLineSegment> lines,
                   ArPose minPose, ArPose maxPose, ArPose lineMinPose, ArPose lineMaxPose,
                   int resolution, List<String> mapInfo) {
    static final MapContents EMPTY = new MapContents(List.of(), List.of(), List.of(), new ArPose(),
            new ArPose(), new ArPose(), new ArPose(), 0, List.of());

    /**
     * @param file a map file as read
     * @return what a robot program sees of it
     */
    static MapContents of(MapFile file) {
        List<ArMapObject> objects = new ArrayList<>();
        for (Cairn c : file.cairns()) {
            objects.add(ArMapObject.of(c));
        }
        MapHeader h = file.header();
        MapBounds points = new MapBounds(h.numPoints(), h.minPos(), h.maxPos());
        Coordinates p = file.pointItems();
        List<ArPose> poses = new ArrayList<>(p.count());
        for (int i = 0; i < p.count(); i++) {
            poses.add(new ArPose(p.get(i, 0), p.get(i, 1)));
            points.add(p.get(i, 0), p.get(i, 1));
        }
        MapBounds lineBounds = new MapBounds(h.numLines(), h.lineMinPos(), h.lineMaxPos());
        Coordinates l = file.lineItems();
        List<ArLineSegment> lines = new ArrayList<>(l.count());
        for (int i = 0; i < l.count(); i++) {
            lines.add(new ArLineSegment(l.get(i, 0), l.get(i, 1), l.get(i, 2), l.get(i, 3)));
            lineBounds.add(l.get(i, 0), l.get(i, 1));
            lineBounds.add(l.get(i, 2), l.get(i, 3));
        }
        return new MapContents(Collections.unmodifiableList(objects), Collections.unmodifiableList(poses),
                Collections.unmodifiableList(lines), points.min(), points.max(), lineBounds.min(), lineBounds.max(),
                (int) file.resolution(), h.mapInfo());
    }
}
