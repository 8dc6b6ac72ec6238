package robosim.env.core;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;
import robosim.env.camera.ColoredShape;
import robosim.env.world.Obstacle;
import robosim.geometry.GeometryClient;
import robosim.protocol.Colors;

/**
 * What the robots' cameras see: the world's walls and obstacles at their heights and colours,
 * and the robots' bodies, uncoloured, {@value #ROBOT_HEIGHT} mm high. Anything else with a colour
 * and a height (a gripper's pucks) joins as one more {@link ColoredShape}.
 */
final class CameraScene {
    /** How high a robot's body stands, mm: a Pioneer 3-DX's body is 237 mm. */
    static final double ROBOT_HEIGHT = 250;

    private final List<ColoredShape> scenery = new ArrayList<>();

    CameraScene(List<Obstacle> obstacles) {
        for (Obstacle o : obstacles) {
            scenery.add(new ColoredShape(o.xy(), o.height(),
                    o.color() == null ? ColoredShape.NO_COLOR : Colors.parse(o.color()), -1));
        }
    }

    /** @return the scenery, the pucks and every robot's body where they stand now */
    List<ColoredShape> now(List<SimRobot> robots, GeometryClient geometry, Pucks pucks) {
        List<ColoredShape> shapes = new ArrayList<>(scenery);
        pucks.addCameraShapes(shapes);
        for (SimRobot r : robots) {
            Coordinate[] ring = geometry.bodyPolygon(r.bodyId).getExteriorRing().getCoordinates();
            double[] xy = new double[2 * (ring.length - 1)];
            for (int i = 0; i < ring.length - 1; i++) {
                xy[2 * i] = ring[i].x;
                xy[2 * i + 1] = ring[i].y;
            }
            shapes.add(new ColoredShape(xy, ROBOT_HEIGHT, ColoredShape.NO_COLOR, r.bodyId));
        }
        return shapes;
    }

    /** @return a robot's camera as viewers draw it, {pan, field of view} in degrees; null while off */
    static double[] drawn(SimRobot r) {
        robosim.protocol.CameraView v = r.sensors().camera();
        return v == null ? null : new double[] {v.pan(), v.model().fieldOfView(v.zoom())};
    }
}
