package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** ARIA's ArMap over a small map file: its objects, lines, points, bounds and errors. */
class ArMapTest {
    /** A 6 m square room with two goals, a dock, a home, a forbidden line and a turned forbidden area. */
    static final String ROOM = """
            2D-Map
            MinPos: 500 500
            MaxPos: 1500 1000
            NumPoints: 3
            LineMinPos: 0 0
            LineMaxPos: 6000 6000
            NumLines: 4
            Resolution: 100
            MapInfo: GoalType Name=Goal
            MapInfo: DockType Name=Dock
            Cairn: RobotHome 1000 1000 90 "" ICON "home"
            Cairn: Goal 5000 5000 0.000000 "" ICON "Far Corner"
            Cairn: GoalWithHeading 1000 5000 180 "" ICON "left" "by the door"
            Cairn: Dock 3000 500 -90 "" ICON "dock1"
            Cairn: ForbiddenLine 0 0 0.000000 "" ICON "" 3000 2000 3000 4000
            Cairn: ForbiddenArea 0 0 90.000000 "" ICON "pit" 1000 0 2000 500
            LINES
            0 0 6000 0
            6000 0 6000 6000
            6000 6000 0 6000
            0 6000 0 0
            DATA
            400 700
            1500 900
            1000 1200
            """;

    @TempDir
    Path dir;

    private ArMap read(String text) throws IOException {
        Files.writeString(dir.resolve("room.map"), text);
        ArMap map = new ArMap(dir.toString());
        assertTrue(map.readFile("room.map"));
        return map;
    }

    private static String logOf(Runnable r) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ArLog.setStream(new PrintStream(out, true, StandardCharsets.UTF_8));
        try {
            r.run();
        } finally {
            ArLog.setStream(null);
        }
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void readsTheObjectsInFileOrder() throws IOException {
        ArMap map = read(ROOM);
        List<ArMapObject> objects = map.getMapObjects();
        assertEquals(List.of("RobotHome", "Goal", "GoalWithHeading", "Dock", "ForbiddenLine", "ForbiddenArea"),
                objects.stream().map(ArMapObject::getType).toList());
        assertEquals(List.of("RobotHome", "Goal", "GoalWithHeading", "Dock", "ForbiddenLine", "ForbiddenArea"),
                map.getMapObjectTypes());
        assertEquals("room.map", map.getFileName());
        ArMapObject left = objects.get(2);
        assertEquals("left", left.getName());
        assertEquals("by the door", left.getDescription());
        assertEquals("Goal", left.getBaseType());
        assertEquals(new ArPose(1000, 5000, 180), left.getPose());
        assertFalse(left.hasFromTo());
    }

    @Test
    void findsObjectsByNameAndTypeIgnoringCase() throws IOException {
        ArMap map = read(ROOM);
        ArMapObject far = map.findMapObject("far corner");
        assertEquals(new ArPose(5000, 5000, 0), far.getPose());
        assertSame(far, map.findMapObject("Far Corner", "goal"));
        assertNull(map.findMapObject("Far Corner", "Dock"));
        assertNull(map.findMapObject("left", "Goal"), "GoalWithHeading is not Goal unless asked");
        assertEquals("left", map.findMapObject("left", "Goal", true).getName());
        assertSame(map.getMapObjects().get(3), map.findFirstMapObject(null, "Dock"));
        assertEquals(List.of("Far Corner", "left"),
                map.findMapObjectsOfType("Goal", true).stream().map(ArMapObject::getName).toList());
        assertEquals(1, map.findMapObjectsOfType("Goal").size());
    }

    @Test
    void readsTheLinesAndPointsWithTheirBounds() throws IOException {
        ArMap map = read(ROOM);
        assertEquals(4, map.getNumLines());
        assertEquals(new ArLineSegment(6000, 0, 6000, 6000), map.getLines().get(1));
        assertEquals(3, map.getNumPoints());
        assertEquals(new ArPose(1000, 1200), map.getPoints().get(2));
        // the header's MinPos and MaxPos, widened by the points read (400 700 and 1000 1200), as ARIA does
        assertEquals(new ArPose(400, 500), map.getMinPose());
        assertEquals(new ArPose(1500, 1200), map.getMaxPose());
        assertEquals(new ArPose(0, 0), map.getLineMinPose());
        assertEquals(new ArPose(6000, 6000), map.getLineMaxPose());
        assertEquals(100, map.getResolution());
        assertEquals(List.of("GoalType Name=Goal", "DockType Name=Dock"), map.getMapInfo());
    }

    @Test
    void withoutHeaderCornersTheBoundsStartAtTheOrigin() throws IOException {
        ArMap map = read("2D-Map\nDATA\n200 300\n900 400\nLINES\n-100 50 20 80\n");
        assertEquals(new ArPose(0, 0), map.getMinPose(), "ARIA starts from (0, 0)");
        assertEquals(new ArPose(900, 400), map.getMaxPose());
        assertEquals(new ArPose(-100, 0), map.getLineMinPose());
        assertEquals(new ArPose(20, 80), map.getLineMaxPose());
        assertEquals(0, map.getResolution());
    }

    @Test
    void aMapDeclaringNoPointsHasTheEmptyExtremes() throws IOException {
        ArMap map = read("2D-Map\nNumPoints: 0\nDATA\n");
        assertEquals(new ArPose(Integer.MAX_VALUE, Integer.MAX_VALUE), map.getMinPose());
        assertEquals(new ArPose(Integer.MIN_VALUE, Integer.MIN_VALUE), map.getMaxPose());
    }

    @Test
    void aBadFileIsFalseWithALogLineNamingFileAndLineAndTheMapStays() throws IOException {
        ArMap map = read(ROOM);
        Files.writeString(dir.resolve("bad.map"), "2D-Map\nNumPoints: 1\nDATA\n10 twenty\n");
        boolean[] ok = {true};
        String log = logOf(() -> ok[0] = map.readFile("bad.map"));
        assertFalse(ok[0]);
        assertTrue(log.contains("ArMap::readFile: " + dir.resolve("bad.map") + ":4: coordinate 'twenty' is not a number"),
                log);
        assertEquals("room.map", map.getFileName(), "the map read before stays");
        assertEquals(6, map.getMapObjects().size());
    }

    @Test
    void aMissingFileIsFalseWithALogLineNamingIt() {
        ArMap map = new ArMap(dir.toString());
        boolean[] ok = {true};
        String log = logOf(() -> ok[0] = map.readFile("none.map"));
        assertFalse(ok[0]);
        assertTrue(log.contains(dir.resolve("none.map") + ": no such map file"), log);
        assertEquals("", map.getFileName());
        assertEquals(List.of(), map.getMapObjects());
    }

    @Test
    void aNameNoFileCanHaveIsAFailedReadAndAnEmptyNameToo() {
        ArMap map = new ArMap(dir.toString());
        boolean[] ok = {true, true};
        String log = logOf(() -> {
            ok[0] = map.readFile("nul\0.map");
            ok[1] = map.readFile("");
        });
        assertFalse(ok[0]);
        assertFalse(ok[1]);
        assertTrue(log.contains("ArMap::readFile: nul\0.map: Nul character not allowed"), log);
        assertTrue(log.contains("ArMap::readFile: no file name given"), log);
    }

    @Test
    void anAbsoluteNameIgnoresTheBaseDirectory() throws IOException {
        Path file = Files.writeString(dir.resolve("abs.map"), ROOM);
        ArMap map = new ArMap("/no/such/dir");
        assertEquals("/no/such/dir/x.map", map.createRealFileName("x.map"));
        assertTrue(map.readFile(file.toString()));
        assertEquals(6, map.getMapObjects().size());
    }

    @Test
    void theMapChangedCallbacksRunAfterEachReadInTheirOrder() throws IOException {
        Files.writeString(dir.resolve("room.map"), ROOM);
        ArMap map = new ArMap(dir.toString());
        StringBuilder order = new StringBuilder();
        AtomicInteger objects = new AtomicInteger();
        map.addMapChangedCB(() -> order.append('b'));
        map.addMapChangedCB(() -> {
            order.append('a');
            objects.set(map.getMapObjects().size());
        }, ArListPos.FIRST);
        assertTrue(map.readFile("room.map"));
        assertEquals("ab", order.toString());
        assertEquals(6, objects.get());
        logOf(() -> map.readFile("none.map"));
        assertEquals("abab", order.toString(), "ARIA runs them after a failed read too");
    }
}
