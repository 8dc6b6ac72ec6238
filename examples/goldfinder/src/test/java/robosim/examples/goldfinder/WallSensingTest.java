package robosim.examples.goldfinder;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.RobotStates;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * Which sides of its cell a Pioneer standing at the cell's centre reads as open, from given laser
 * and rear sonar ranges (a side is open when the echo that way lies farther than 0.6 of a cell
 * from the robot's centre), and what its laser tells of any side in view from anywhere, from the
 * scans it would read of walls given as boxes.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class WallSensingTest {
    private static final int E = 1;
    private static final int N = 2;
    private static final int W = 4;
    private static final int S = 8;
    /** The laser sits 18 mm ahead of the centre, as on a p3dx. */
    private static final double LASER_X = 18;
    /** The p3dx's sonar ring; the rear pair, 11 and 12, face -170° and 170°, 255 mm behind the centre. */
    private static final List<SonarUnit> P3DX_SONARS = List.of(
            new SonarUnit(0, 69, 136, 90), new SonarUnit(1, 114, 119, 50), new SonarUnit(2, 148, 78, 30),
            new SonarUnit(3, 166, 27, 10), new SonarUnit(4, 166, -27, -10), new SonarUnit(5, 148, -78, -30),
            new SonarUnit(6, 114, -119, -50), new SonarUnit(7, 69, -136, -90), new SonarUnit(8, -157, -136, -90),
            new SonarUnit(9, -203, -119, -130), new SonarUnit(10, -237, -78, -150),
            new SonarUnit(11, -255, -27, -170), new SonarUnit(12, -255, 27, 170),
            new SonarUnit(13, -237, 78, 150), new SonarUnit(14, -203, 119, 130), new SonarUnit(15, -157, 136, 90));

    private static RobotParameters p3dx(List<SonarUnit> sonars) {
        return new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500, 300, 300, 100, 100,
                0.0056, 5000, sonars, LASER_X, 0, 0, 8000);
    }

    /** A Pioneer with no Environment: each reading is handed to it as one cycle's state. */
    private static final class StandingPioneer extends ArRobot {
        final ArSick laser = new ArSick();

        StandingPioneer(RobotParameters parameters) {
            super("r1", "127.0.0.1", 5000, parameters);
            addRangeDevice(laser);
        }

        /** One cycle at (x, y), facing {@code th}, with a laser scan and no sonar. */
        void at(double x, double y, double th, int[] laser) {
            responded(new RobotSensorResponse(RobotStates.of(1, 100, x, y, th, 0, 0, 0, 0, false, new int[0], 0,
                    laser, null)));
        }

        /** One cycle standing at the centre of cell (0, 0) of a 1500 mm maze, facing {@code th}. */
        void reads(double th, int[] laser, int[] sonar) {
            responded(new RobotSensorResponse(RobotStates.of(1, 100, 750, 750, th, 0, 0, 0, 0, false, sonar, 0,
                    laser, null)));
        }
    }

    /** A 1° scan (181 readings, right to left) of {@code others} but for the beams given as index, range pairs. */
    private static int[] scan(int others, int... indexRange) {
        return scanOf(181, others, indexRange);
    }

    private static int[] scanOf(int readings, int others, int... indexRange) {
        int[] s = new int[readings];
        Arrays.fill(s, others);
        for (int k = 0; k < indexRange.length; k += 2) {
            s[indexRange[k]] = indexRange[k + 1];
        }
        return s;
    }

    /** Every sonar reads {@code others} but the rear pair, 11 and 12. */
    private static int[] sonar(int others, int sonar11, int sonar12) {
        int[] s = new int[16];
        Arrays.fill(s, others);
        s[11] = sonar11;
        s[12] = sonar12;
        return s;
    }

    private static int openSides(double th, int[] laser, int[] sonar, double cellSize) {
        StandingPioneer robot = new StandingPioneer(p3dx(P3DX_SONARS));
        robot.reads(th, laser, sonar);
        return WallSensing.openSides(robot, robot.laser, cellSize);
    }

    @Test
    void wallsOnAllFourEdgesOfTheCellCloseEverySide() {
        // 1500 mm cells: each wall 750 mm from the centre; the laser is 18 mm nearer the wall ahead,
        // the rear sonars 255 mm nearer the wall behind
        assertEquals(0, openSides(0, scan(750, 90, 732), sonar(750, 495, 495), 1500));
    }

    @Test
    void facingEastTheLaserReadsEastNorthAndSouthAndTheRearSonarsWest() {
        assertEquals(E, openSides(0, scan(750, 90, 2232), sonar(750, 495, 495), 1500), "the far wall ahead");
        assertEquals(N, openSides(0, scan(750, 90, 732, 180, 2250), sonar(750, 495, 495), 1500), "left");
        assertEquals(S, openSides(0, scan(750, 90, 732, 0, 2250), sonar(750, 495, 495), 1500), "right");
        assertEquals(W, openSides(0, scan(750, 90, 732), sonar(750, 1995, 1995), 1500), "behind");
    }

    @Test
    void facingNorthAheadIsNorthAndTheRightIsEast() {
        assertEquals(N | E, openSides(90, scan(750, 90, 2232, 0, 2250), sonar(750, 495, 495), 1500));
    }

    @Test
    void facingWestTheRearSonarsReadEast() {
        assertEquals(E | S, openSides(180, scan(750, 90, 732, 180, 2250), sonar(750, 1995, 1995), 1500));
    }

    @Test
    void facingSouthTheLeftIsEastAndTheRightIsWest() {
        assertEquals(E | S, openSides(-90, scan(750, 90, 2232, 180, 2250), sonar(750, 495, 495), 1500));
        assertEquals(W, openSides(-90, scan(750, 90, 732, 0, 2250), sonar(750, 495, 495), 1500));
    }

    @Test
    void aSideIsOpenOnlyWhenItsEchoLiesBeyondSixTenthsOfACell() {
        // 1000 mm cells: open beyond 600 mm from the centre; ahead, the laser's 18 mm count
        assertEquals(0, openSides(0, scan(500, 90, 582), sonar(500, 300, 300), 1000), "582 + 18 = 600");
        assertEquals(E, openSides(0, scan(500, 90, 583), sonar(500, 300, 300), 1000), "583 + 18 = 601");
    }

    @Test
    void theLasersOffsetDoesNotLengthenTheSideBeams() {
        assertEquals(0, openSides(0, scan(500, 180, 599), sonar(500, 300, 300), 1000));
        assertEquals(N, openSides(0, scan(500, 180, 601), sonar(500, 300, 300), 1000));
    }

    @Test
    void behindTheRangeIsMeasuredFromTheCentreThroughTheRearSonars() {
        // the rear sonars sit 255 mm behind the centre
        assertEquals(0, openSides(0, scan(500), sonar(500, 345, 345), 1000), "345 + 255 = 600");
        assertEquals(W, openSides(0, scan(500), sonar(500, 346, 346), 1000), "346 + 255 = 601");
    }

    @Test
    void theNearerOfTheTwoRearSonarsDecides() {
        assertEquals(0, openSides(0, scan(500), sonar(500, 2000, 300), 1000));
        assertEquals(0, openSides(0, scan(500), sonar(500, 300, 2000), 1000));
    }

    @Test
    void onlyTheRearSonarsJudgeTheSideBehind() {
        // sonars 10 and 13 (at ±150°) see a near echo, 11 and 12 (at ±170°) a far one
        int[] sonar = sonar(500, 2000, 2000);
        sonar[10] = 100;
        sonar[13] = 100;
        assertEquals(W, openSides(0, scan(500), sonar, 1000));
    }

    @Test
    void aTeammateStandingInTheNextCellLeavesTheSideOpen() {
        // a p3dx at the next cell's centre, 1500 mm ahead, shows its rear 301 mm before that centre
        assertEquals(E, openSides(0, scan(750, 90, 1500 - 301 - 18), sonar(750, 495, 495), 1500));
    }

    @Test
    void aHalfDegreeScanIsReadAtTheSameAngles() {
        // 361 readings: ahead is reading 180, left 360, right 0
        int[] laser = scanOf(361, 750, 180, 732, 360, 2250, 90, 9000);
        assertEquals(N, openSides(0, laser, sonar(750, 495, 495), 1500));
    }

    @Test
    void aHeadingSlightlyOffTheAxisReadsTheBeamsNearestEachSide() {
        // facing -0.4°: east is 0.4° left of ahead (beam 90), north beyond the left end (beam 180),
        // south 89.6° right (beam 0)
        int[] laser = scan(750, 90, 2232, 180, 2250, 0, 2250, 1, 100, 179, 100);
        assertEquals(E | N | S, openSides(-0.4, laser, sonar(750, 495, 495), 1500));
    }

    @Test
    void aRobotWithoutRearSonarsReadsTheSideBehindAsClosed() {
        StandingPioneer robot = new StandingPioneer(p3dx(List.of()));
        robot.reads(0, scan(2250), new int[0]);
        assertEquals(E | N | S, WallSensing.openSides(robot, robot.laser, 1500));
    }

    // ---- any side in view, from anywhere ----

    /**
     * A corridor along row 0 of a 1500 mm maze, cells (0, 0) to (2, 0): the boundary walls along its
     * south side and its west end (100 mm thick, just inside the world), an inner wall (100 mm thick, centred on
     * y = 1500) along its north side but for cell (2, 0), which opens north onto a room closed at
     * y = 3000, and an inner wall closing its east end at x = 4500.
     */
    private static final double[][] CORRIDOR = {
            {0, 0, 4500, 100}, {0, 0, 100, 3000}, {-50, 1450, 3050, 1550}, {4450, -50, 4550, 3050}, {-50, 2950, 4550, 3050}};

    /** The 1° scan a laser 18 mm ahead of (x, y), facing {@code th}, reads of the boxes {x0, y0, x1, y1}. */
    private static int[] cast(double x, double y, double th, double[]... boxes) {
        int[] s = new int[181];
        double lx = x + LASER_X * Math.cos(Math.toRadians(th));
        double ly = y + LASER_X * Math.sin(Math.toRadians(th));
        for (int i = 0; i < s.length; i++) {
            double a = Math.toRadians(th + i - 90);
            double dx = Math.cos(a);
            double dy = Math.sin(a);
            double best = 8000;
            for (double[] b : boxes) {
                double t0 = 0;
                double t1 = best;
                double[] lo = {b[0] - lx, b[1] - ly};
                double[] hi = {b[2] - lx, b[3] - ly};
                double[] d = {dx, dy};
                for (int k = 0; k < 2 && t0 <= t1; k++) {
                    if (Math.abs(d[k]) < 1e-12) {
                        t0 = lo[k] <= 0 && hi[k] >= 0 ? t0 : Double.POSITIVE_INFINITY;
                    } else {
                        t0 = Math.max(t0, Math.min(lo[k] / d[k], hi[k] / d[k]));
                        t1 = Math.min(t1, Math.max(lo[k] / d[k], hi[k] / d[k]));
                    }
                }
                if (t0 <= t1) {
                    best = Math.min(best, t0);
                }
            }
            s[i] = (int) Math.round(best);
        }
        return s;
    }

    private static double[][] with(double[][] boxes, double[] more) {
        double[][] out = Arrays.copyOf(boxes, boxes.length + 1);
        out[boxes.length] = more;
        return out;
    }

    /** What a robot at (x, y) facing {@code th} reads of side {@code d} of cell (cx, cy), among the boxes. */
    private static int side(double x, double y, double th, double[][] boxes, int cx, int cy, int d) {
        StandingPioneer robot = new StandingPioneer(p3dx(P3DX_SONARS));
        robot.at(x, y, th, cast(x, y, th, boxes));
        return WallSensing.side(robot, robot.laser.getRawScan(), 1500, cx, cy, d);
    }

    @Test
    void drivingAlongACorridorTheLaserReadsTheWallsAndOpeningsAhead() {
        assertEquals(WallSensing.CLOSED, side(1000, 750, 0, CORRIDOR, 1, 0, 1), "the inner wall north of (1, 0)");
        assertEquals(WallSensing.OPEN, side(2250, 750, 0, CORRIDOR, 2, 0, 1), "(2, 0) opens north");
        assertEquals(WallSensing.OPEN, side(1000, 750, 0, CORRIDOR, 1, 0, 0), "(1, 0) opens east onto (2, 0)");
        assertEquals(WallSensing.CLOSED, side(1000, 750, 0, CORRIDOR, 2, 0, 0), "the end wall");
    }

    @Test
    void theBoundaryWallJustInsideTheWorldReadsClosed() {
        assertEquals(WallSensing.CLOSED, side(1000, 750, 0, CORRIDOR, 1, 0, 3));
        assertEquals(WallSensing.CLOSED, side(2250, 750, 0, CORRIDOR, 2, 0, 3));
    }

    @Test
    void aSideBesideTheRobotIsReadOnlyWhenTwoOfItsMarksAreInView() {
        assertEquals(WallSensing.UNSEEN, side(2250, 750, 0, CORRIDOR, 1, 0, 1), "one mark ahead of the laser");
        assertEquals(WallSensing.CLOSED, side(1900, 750, 0, CORRIDOR, 1, 0, 1), "two marks ahead of the laser");
    }

    @Test
    void aSideBehindTheLaserIsUnseen() {
        assertEquals(WallSensing.UNSEEN, side(1000, 750, 0, CORRIDOR, 0, 0, 2));
        assertEquals(WallSensing.CLOSED, side(1000, 750, 180, CORRIDOR, 0, 0, 2), "facing it, it is read");
    }

    @Test
    void aTeammateStandingInADoorwayNeverClosesIt() {
        double[][] across = with(CORRIDOR, new double[] {3550, 1300, 3950, 1700});
        assertEquals(WallSensing.UNSEEN, side(2250, 750, 0, across, 2, 0, 1), "in the middle it hides the side");
        double[][] aside = with(CORRIDOR, new double[] {3900, 1300, 4300, 1700});
        assertEquals(WallSensing.OPEN, side(2250, 750, 0, aside, 2, 0, 1), "to one side a beam goes past it");
    }

    @Test
    void somethingNearerThanASideHidesIt() {
        double[][] mate = with(CORRIDOR, new double[] {2100, 550, 2500, 950});
        assertEquals(WallSensing.UNSEEN, side(1000, 750, 0, mate, 2, 0, 0), "a teammate in (1, 0) hides the end wall");
    }

    @Test
    void aSideMetTooShallowIsUnseen() {
        // from the west end of the corridor the beams aimed at the boundary wall south of (2, 0) meet it at about 14°
        assertEquals(WallSensing.UNSEEN, side(300, 750, 0, CORRIDOR, 2, 0, 3));
    }
}
