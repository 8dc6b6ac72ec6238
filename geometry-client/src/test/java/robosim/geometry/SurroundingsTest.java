package robosim.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Polygon;

/** Gathered surroundings answer exactly what the whole-world queries answer. */
class SurroundingsTest {
    private static GeometryClient clutteredWorld(Random rnd) {
        List<Polygon> obstacles = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            double x = rnd.nextDouble() * 20000;
            double y = rnd.nextDouble() * 20000;
            double w = 100 + rnd.nextDouble() * 800;
            double h = 100 + rnd.nextDouble() * 800;
            obstacles.add(GeometryClient.polygon(x, y, x + w, y, x + w, y + h, x, y + h));
        }
        GeometryClient g = new GeometryClient(obstacles);
        for (int i = 0; i < 10; i++) {
            g.addBody(BodyShape.rectangle(210, 301, 425),
                    new Pose2D(rnd.nextDouble() * 20000, rnd.nextDouble() * 20000, rnd.nextDouble() * 6.28));
        }
        return g;
    }

    @Test
    void conesFromAroundARobotMatchWholeWorldCones() {
        Random rnd = new Random(7);
        GeometryClient g = clutteredWorld(rnd);
        for (int k = 0; k < 300; k++) {
            double x = rnd.nextDouble() * 20000;
            double y = rnd.nextDouble() * 20000;
            Surroundings near = g.around(x, y, 5000 + 300, 3);
            for (int s = 0; s < 16; s++) {
                double ax = x + (rnd.nextDouble() - 0.5) * 500;
                double ay = y + (rnd.nextDouble() - 0.5) * 500;
                double th = rnd.nextDouble() * 2 * Math.PI - Math.PI;
                double half = Math.toRadians(15);
                assertEquals(g.coneRange(ax, ay, th, half, 5000, 3), near.cone(ax, ay, th, half, 5000), 1e-9,
                        "cone " + k + "/" + s);
                assertEquals(g.rayRange(ax, ay, th, 5000, 3), near.ray(ax, ay, th, 5000), 1e-9, "ray " + k + "/" + s);
            }
        }
    }

    @Test
    void surroundingsGatheredIntoAgainAnswerAsNewOnes() {
        Random rnd = new Random(11);
        GeometryClient g = clutteredWorld(rnd);
        Surroundings reused = new Surroundings();
        for (int k = 0; k < 200; k++) {
            double x = rnd.nextDouble() * 20000;
            double y = rnd.nextDouble() * 20000;
            // radii up and down, so the arrays hold more edges than the latest gathering at times
            double radius = 500 + rnd.nextDouble() * 8000;
            Surroundings fresh = g.around(x, y, radius, 3);
            assertSame(reused, g.gather(x, y, radius, 3, reused));
            assertEquals(fresh.edges(), reused.edges(), "gathering " + k);
            for (int s = 0; s < 16; s++) {
                double th = rnd.nextDouble() * 2 * Math.PI - Math.PI;
                assertEquals(fresh.cone(x, y, th, 0.26, radius), reused.cone(x, y, th, 0.26, radius), 0.0);
                assertEquals(fresh.ray(x, y, th, radius), reused.ray(x, y, th, radius), 0.0);
            }
        }
    }

    @Test
    void theOwnBodyIsLeftOut() {
        GeometryClient g = new GeometryClient(List.of());
        int id = g.addBody(BodyShape.rectangle(200, 200, 400), new Pose2D(0, 0, 0));
        assertEquals(0, g.around(0, 0, 6000, id).size());
        assertEquals(4, g.around(0, 0, 6000, -1).size());
        assertEquals(5000, g.around(0, 0, 6000, id).cone(0, 0, 0, 0.26, 5000), 0.0);
    }
}
