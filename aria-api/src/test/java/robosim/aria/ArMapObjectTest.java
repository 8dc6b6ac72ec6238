package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.map.Cairn;

/** ARIA's ArMapObject: poses, from and to points, a turned area's sides, its Cairn line. */
class ArMapObjectTest {
    private static final double TOLERANCE = 1e-9;

    private static void assertPose(double x, double y, ArPose p) {
        assertEquals(x, p.getX(), TOLERANCE, "x of " + p);
        assertEquals(y, p.getY(), TOLERANCE, "y of " + p);
    }

    @Test
    void aGoalIsAPoseWithANameAndItsCairnLine() {
        ArMapObject goal = ArMapObject.of(new Cairn("Goal", 5000, 5000, 0, "", "ICON", "Far Corner", new double[0], 3));
        assertEquals("Goal", goal.getType());
        assertEquals("Goal", goal.getBaseType());
        assertEquals("Far Corner", goal.getName());
        assertEquals("", goal.getDescription());
        assertEquals("ICON", goal.getIconName());
        assertEquals(0, goal.getId());
        assertEquals(List.of(), goal.getFromToSegments());
        assertEquals(0, goal.getFromToRotation());
        assertEquals(new ArPose(5000, 5000, 0), goal.findCenter());
        assertEquals("Goal 5000 5000 0.000000 \"\" ICON \"Far Corner\"", goal.toString());
    }

    @Test
    void anIdIconGivesTheNumber() {
        ArMapObject g = new ArMapObject("GoalWithHeading", new ArPose(1, 2, 30), "d", "ID=17", "g", false,
                new ArPose(), new ArPose());
        assertEquals(17, g.getId());
        assertEquals("Goal", g.getBaseType());
    }

    @Test
    void aForbiddenLineIsItsFromToSegment() {
        ArMapObject line = ArMapObject.of(new Cairn("ForbiddenLine", 0, 0, 0, "", "ICON", "",
                new double[] {3000, 2000, 3000, 4000}, 5));
        assertTrue(line.hasFromTo());
        assertEquals(new ArLineSegment(3000, 2000, 3000, 4000), line.getFromToSegment());
        assertEquals("ForbiddenLine", line.getBaseType());
        assertEquals("ForbiddenLine 0 0 0.000000 \"\" ICON \"\" 3000 2000 3000 4000", line.toString());
    }

    @Test
    void aForbiddenAreaIsTurnedByItsHeadingAboutTheOrigin() {
        // from (1000, 0) to (2000, 500), turned 90 degrees: x' = -y, y' = x
        ArMapObject area = ArMapObject.of(new Cairn("ForbiddenArea", 0, 0, 90, "", "ICON", "pit",
                new double[] {1000, 0, 2000, 500}, 6));
        List<ArPose> corners = area.getRegionVertices();
        assertPose(0, 1000, corners.get(0));
        assertPose(0, 2000, corners.get(1));
        assertPose(-500, 2000, corners.get(2));
        assertPose(-500, 1000, corners.get(3));
        List<ArLineSegment> sides = area.getFromToSegments();
        assertEquals(4, sides.size());
        for (int i = 0; i < 4; i++) {
            assertPose(corners.get(i).getX(), corners.get(i).getY(), sides.get(i).getEndPoint1());
            assertPose(corners.get((i + 1) % 4).getX(), corners.get((i + 1) % 4).getY(), sides.get(i).getEndPoint2());
        }
        assertEquals(90, area.getFromToRotation());
        assertPose(-250, 1500, area.findCenter());
        assertPose(1000, 0, area.getFromPose());
        assertPose(2000, 500, area.getToPose());
    }

    @Test
    void anUnturnedAreaHasItsCornersAsWritten() {
        ArMapObject area = ArMapObject.of(new Cairn("ForbiddenArea", 0, 0, 0, "", "ICON", "",
                new double[] {-2500, 2500, -1500, 3500}, 6));
        assertEquals(List.of(new ArLineSegment(-2500, 2500, -1500, 2500), new ArLineSegment(-1500, 2500, -1500, 3500),
                new ArLineSegment(-1500, 3500, -2500, 3500), new ArLineSegment(-2500, 3500, -2500, 2500)),
                area.getFromToSegments());
    }
}
