package robosim.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Where the polar plot puts the sonar rays and laser hits: in the robot's frame, x forward, y left. */
class ReadingsTest {
    @Test
    void aSonarRayGoesFromItsTransducerAlongItsAngle() {
        List<Readings.Ray> rays = Readings.sonarRays(Fixtures.robot(1000, 100), new int[] {400, 250});
        assertEquals(new Readings.Point(100, 0), rays.get(0).from());
        assertEquals(new Readings.Point(500, 0), rays.get(0).to());
        assertEquals(0, rays.get(1).to().x(), 1e-9);
        assertEquals(350, rays.get(1).to().y(), 1e-9);
    }

    @Test
    void aSonarWithoutAReadingIsLeftOut() {
        List<Readings.Ray> rays = Readings.sonarRays(Fixtures.robot(1000, 100), new int[] {-1, 250});
        assertEquals(1, rays.size());
        assertEquals(250, rays.get(0).range());
    }

    @Test
    void aLaserScanRunsFromTheRightToTheLeftAndMissesAreLeftOut() {
        // three readings: right (-90°), ahead (0°), left (90°); the one ahead hits nothing
        List<Readings.Point> hits = Readings.laserHits(Fixtures.robot(1000, 100), new int[] {1000, 8000, 500}, 8000);
        assertEquals(2, hits.size());
        assertEquals(20, hits.get(0).x(), 1e-9);
        assertEquals(-1000, hits.get(0).y(), 1e-9);
        assertEquals(20, hits.get(1).x(), 1e-9);
        assertEquals(500, hits.get(1).y(), 1e-9);
    }

    @Test
    void theNearestSonarIsTheShortestRay() {
        Readings r = new Readings(1, 100, 0, 0, 0, 0, 0, false, true,
                Readings.sonarRays(Fixtures.robot(1000, 100), new int[] {900, 300}), false, List.of(), null, 5000);
        assertEquals(300, r.nearestSonar());
    }
}
