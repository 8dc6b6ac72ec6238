package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.env.world.ForbiddenZone;
import robosim.env.world.RobotToPlace;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;

/**
 * The ARIA map that ships, {@code testLoadFiles/environment/office.map}, with the robots the README's
 * tour runs on it: {@code env office.map --robot p3dx:r1 --robot p3dx:r2}, and one {@code p3dx} without.
 */
class ShippedMapTest {
    private static final Path OFFICE = WorldFixtures.root().resolve("testLoadFiles/environment/office.map");

    @Test
    void theTourRobotsStartAtTheTwoHomes() {
        World w = WorldReader.read(OFFICE, List.of(new RobotToPlace("p3dx", "r1"), new RobotToPlace("p3dx", "r2")));
        assertEquals(List.of("r1", "r2"), w.robots().stream().map(RobotSpec::name).toList());
        RobotSpec r1 = w.robots().get(0);
        RobotSpec r2 = w.robots().get(1);
        assertEquals(List.of(1500.0, 1500.0, 0.0), List.of(r1.x(), r1.y(), r1.th()));
        assertEquals(List.of(1500.0, 4500.0, 0.0), List.of(r2.x(), r2.y(), r2.th()));
        assertEquals("pioneer", r1.type());
        assertEquals("p3dx", r1.parameters().subclass());
    }

    @Test
    void withoutRobotsItHasOneP3dxAtTheFirstHome() {
        World w = WorldReader.read(OFFICE);
        assertEquals(List.of("p3dx_1"), w.robots().stream().map(RobotSpec::name).toList());
        assertEquals(1500, w.robots().get(0).x());
        assertEquals(1500, w.robots().get(0).y());
    }

    @Test
    void itIsA12By8mOfficeOfEightWallsADeskAPillarAndAForbiddenArea() {
        World w = WorldReader.read(OFFICE);
        assertEquals("office", w.name());
        // the map's lines and points, with 1 m to spare on each side
        assertEquals(List.of(-1000.0, -1000.0, 14000.0, 10000.0), List.of(w.minX(), w.minY(), w.width(), w.height()));
        // 8 walls; the desk's outline merges into its four sides; the pillar's 24 points stay apart or merge
        assertEquals(8, w.obstacles().stream().filter(o -> o.line() >= 14 && o.line() <= 21).count());
        assertEquals(List.of(true), w.zones().stream().map(ForbiddenZone::area).toList());
    }
}
