package robosim.viewer.view3d;

import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.util.List;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.viewer.draw.ClosedPath;
import robosim.viewer.draw.Departures;
import robosim.viewer.draw.LaserPainter;
import robosim.viewer.draw.SonarPainter;
import robosim.viewer.draw.TrailPainter;
import robosim.viewer.draw.WorldRenderer;

/**
 * What the 3D view draws on the floor for each robot, before the walls and robots hide what they
 * stand in front of: its laser scan and sonar rays when shown (by the 2D view's painters, projected
 * onto the floor), and for a robot gone from the run the dashed outline of where it stopped, as
 * the 2D view draws it. The {@link SolidRenderer}'s helper.
 */
final class FloorMarks {
    private FloorMarks() {
    }

    static void draw(Graphics2D g, Projection p, WorldDescription world, Snapshot snapshot, SceneOptions options) {
        TrailPainter.ToScreen floor = (x, y, out) -> {
            out[0] = p.px(x, y, 0);
            out[1] = p.py(x, y, 0);
        };
        List<RobotInfo> infos = world.robots();
        List<RobotView> robots = snapshot.robots();
        for (int i = 0; i < robots.size(); i++) {
            RobotView r = robots.get(i);
            if (!Double.isFinite(r.x()) || !Double.isFinite(r.y()) || !Double.isFinite(r.th())) {
                continue;
            }
            RobotInfo info = infos.stream().filter(x -> x.name().equals(r.name())).findFirst().orElse(null);
            if (Departures.gone(snapshot, r)) {
                outline(g, p, SceneBuilder.footprint(r, info));
                continue;
            }
            int index = colourIndex(infos, r.name(), i);
            if (options.showLaser()) {
                LaserPainter.drawScan(g, floor, r, info, WorldRenderer.robotColour(r, index));
            }
            if (options.showSonar()) {
                SonarPainter.drawRays(g, floor, r, info, WorldRenderer.rayColour(r, index));
            }
        }
    }

    /** @return the robot's colour index as the 2D view counts it: the world's order, then the snapshot's */
    private static int colourIndex(List<RobotInfo> infos, String name, int inSnapshot) {
        for (int i = 0; i < infos.size(); i++) {
            if (infos.get(i).name().equals(name)) {
                return i;
            }
        }
        return infos.size() + inSnapshot;
    }

    private static void outline(Graphics2D g, Projection p, double[] ring) {
        Path2D path = ClosedPath.of(ring.length / 2, i -> p.px(ring[2 * i], ring[2 * i + 1], 0),
                i -> p.py(ring[2 * i], ring[2 * i + 1], 0));
        g.setColor(WorldRenderer.GONE_OUTLINE);
        g.setStroke(WorldRenderer.GONE_STROKE);
        g.draw(path);
    }

}
