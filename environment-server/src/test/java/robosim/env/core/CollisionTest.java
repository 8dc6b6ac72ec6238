package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Polygon;
import robosim.geometry.GeometryClient;
import robosim.protocol.Command;
import robosim.protocol.RobotState;

class CollisionTest {
    private static void run(Simulation sim, int steps) {
        for (int i = 0; i < steps; i++) {
            sim.step(Map.of());
        }
    }

    @Test
    void drivingIntoAWallStopsAtContactAndStalls() {
        // wall face at x = 3000; the p3dx front is 210 mm ahead of its centre
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.SetVel(800))));
        run(sim, 100);
        RobotState s = sim.state("r");
        assertTrue(s.stalled());
        assertEquals(1, s.collisions());
        assertEquals(3000 - 210, s.x(), 0.5, "front at the wall face");
        assertTrue(s.x() <= 2790, "not inside the wall: " + s.x());
        assertFalse(sim.overlapsAnything("r"));
    }

    @Test
    void drivingIntoACornerStopsAtContactNotInside() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000,
                List.of(Worlds.box(3000, 0, 3100, 10000), Worlds.box(0, 3000, 10000, 3100)),
                Worlds.robot("r", 1500, 1500, 45)));
        sim.step(Map.of("r", List.of(new Command.SetVel(600))));
        run(sim, 100);
        RobotState s = sim.state("r");
        assertTrue(s.stalled());
        assertFalse(sim.overlapsAnything("r"));
        Polygon wallX = GeometryClient.polygon(3000, 0, 3100, 0, 3100, 10000, 3000, 10000);
        Polygon wallY = GeometryClient.polygon(0, 3000, 10000, 3000, 10000, 3100, 0, 3100);
        Polygon body = GeometryClient.polygon(corners(s.x(), s.y(), s.th()));
        double gap = Math.min(body.distance(wallX), body.distance(wallY));
        assertTrue(gap < 1.0, "touching one of the walls: gap " + gap);
    }

    @Test
    void aFastRobotDoesNotPassThroughAThinWall() {
        // 3 m per step against a 10 mm wall
        Simulation sim = new Simulation(Worlds.world(20000, 10000, List.of(Worlds.box(3000, 0, 3010, 10000)),
                Worlds.robot("r", 1000, 5000, 0, Worlds.p3dxWith(30000, 300000))));
        sim.step(Map.of("r", List.of(new Command.SetVel(30000))));
        run(sim, 5);
        RobotState s = sim.state("r");
        assertTrue(s.stalled());
        assertTrue(s.x() < 3000, "still before the wall: " + s.x());
        assertEquals(2790, s.x(), 0.5);
    }

    @Test
    void twoRobotsHeadOnStopWithoutOverlapping() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(),
                Worlds.robot("a", 2000, 5000, 0), Worlds.robot("b", 5000, 5000, 180)));
        sim.step(Map.of("a", List.of(new Command.SetVel(500)), "b", List.of(new Command.SetVel(500))));
        run(sim, 100);
        assertTrue(sim.state("a").stalled());
        assertTrue(sim.state("b").stalled());
        assertFalse(sim.overlapsAnything("a"));
        assertFalse(sim.overlapsAnything("b"));
        assertEquals(210 + 210, sim.state("b").x() - sim.state("a").x(), 1.0, "front to front");
    }

    @Test
    void aStalledRobotBacksAwayFreely() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(Worlds.box(3000, 0, 3100, 10000)),
                Worlds.robot("r", 2700, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.SetVel(300))));
        run(sim, 20);
        assertTrue(sim.state("r").stalled());
        sim.step(Map.of("r", List.of(new Command.SetVel(-300))));
        run(sim, 20);
        assertFalse(sim.state("r").stalled());
        assertTrue(sim.state("r").x() < 2600);
        assertEquals(1, sim.state("r").collisions());
    }

    static double[] corners(double x, double y, double th) {
        double c = Math.cos(Math.toRadians(th));
        double s = Math.sin(Math.toRadians(th));
        double[][] local = {{210, 212.5}, {-301, 212.5}, {-301, -212.5}, {210, -212.5}};
        double[] xy = new double[8];
        for (int i = 0; i < 4; i++) {
            xy[2 * i] = x + local[i][0] * c - local[i][1] * s;
            xy[2 * i + 1] = y + local[i][0] * s + local[i][1] * c;
        }
        return xy;
    }
}
