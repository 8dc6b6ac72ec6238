package robosim.examples.goldfinder;

import java.util.HashSet;
import java.util.Set;
import java.util.SplittableRandom;
import robosim.aria.ArHeatSensor;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;
import robosim.aria.ArUtil;
import robosim.hw.RobotMessage;

/**
 * A Pioneer that searches a grid maze for gold by its sensors alone, with its team.
 *
 * <p>It explores cell by cell: standing at a cell's centre it tells the open sides from its laser
 * and rear sonars ({@link WallSensing}), tells its team what it found and where it goes next
 * ({@link MazeMessage}), then drives to an unexplored open neighbour that no teammate holds or has
 * claimed, or, if there is none, one step along the shortest known path to the nearest cell with
 * an unexplored open side (a frontier). Teammates' claims spread the team out. A robot waits for a
 * cell a teammate holds; when two wait on each other, the one with the higher number backs away
 * into a free neighbour, so the one with the lower number goes first.
 *
 * <p>A heat sensor with a 360° view guides it: when the gold's heat is sensed through an open side,
 * that side is taken first. The robot has found the gold when its heat sensor places the gold
 * within {@value #FOUND_DISTANCE} mm; it reports the find to the Environment and broadcasts it,
 * and every teammate that hears it stops.
 */
public class Gold extends ArRobot {
    /** The gold is found when the heat sensor places it this near, mm. */
    public static final double FOUND_DISTANCE = 1000;
    private static final int PATIENCE = 25;

    private enum Phase { DECIDE, ANNOUNCE, TURN, MOVE, BACK, DONE }

    private final double cellSize;
    private final int rank;
    private final SplittableRandom random;
    private final MazeKnowledge map = new MazeKnowledge();
    private final ArSick laser = new ArSick();
    private final ArHeatSensor heat;
    private Phase phase = Phase.DECIDE;
    private int cx;
    private int cy;
    private int dir = -1;
    private int waited;
    private int pause;
    private double startX;
    private double startY;
    private String finder;

    /**
     * @param name     the robot's name, {@code r<number>}: lower numbers go first where robots meet
     * @param host     the Environment's host
     * @param port     its robot port
     * @param cellSize the maze's cell size, mm
     * @param seed     the seed of the robot's tie-breaks
     */
    public Gold(String name, String host, int port, double cellSize, long seed) {
        super(name, host, port, "p3dx");
        this.cellSize = cellSize;
        this.rank = rankOf(name);
        this.random = new SplittableRandom(seed * 31 + rank);
        this.heat = new ArHeatSensor(360, 3 * cellSize);
        addRangeDevice(laser);
    }

    private static int rankOf(String name) {
        String digits = name.replaceAll("\\D", "");
        return digits.isEmpty() ? Math.abs(name.hashCode() % 1000) : Integer.parseInt(digits);
    }

    /**
     * Runs one Gold robot, as the original's robot applications.
     *
     * @param args NAME HOST PORT CELLSIZE [SEED]
     */
    public static void main(String[] args) {
        if (args.length < 4) {
            throw new IllegalArgumentException("usage: Gold NAME HOST PORT CELLSIZE [SEED]");
        }
        Gold robot = new Gold(args[0], args[1], Integer.parseInt(args[2]), Double.parseDouble(args[3]),
                args.length > 4 ? Long.parseLong(args[4]) : 1);
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + robot.getConnectionError());
        }
        robot.search();
        robot.disconnect();
    }

    /**
     * Enables the motors (a Pioneer's are disabled when its program connects, as in ARIA), then
     * searches until the gold is found (by anyone) or the run ends; then stands still until the end.
     */
    public void search() {
        enableMotors();
        laser.blockingConnect();
        heat.attach(this);
        cx = (int) Math.floor(getX() / cellSize);
        cy = (int) Math.floor(getY() / cellSize);
        ArUtil.sleep(getStepMs());
        while (isConnected()) {
            cycle();
            ArUtil.sleep(getStepMs());
        }
    }

    /** @return who found the gold, as far as this robot knows, or null */
    public String getFinder() {
        return finder;
    }

    /** One step's worth of listening, sensing and driving. */
    void cycle() {
        listen();
        if (phase == Phase.DONE) {
            return;
        }
        if (finder != null) {
            stop();
            phase = Phase.DONE;
            return;
        }
        if (heat.senses() && heat.getDistance() <= FOUND_DISTANCE) {
            finder = getName();
            long foundStep = getStep();
            stop();
            reportFound("gold");
            tell(-1, -1, true);
            say("found the gold at step " + foundStep);
            phase = Phase.DONE;
            return;
        }
        switch (phase) {
            case DECIDE -> decide();
            case ANNOUNCE -> announce();
            case TURN -> turn();
            case MOVE -> drive();
            case BACK -> back();
            default -> { }
        }
    }

    private void listen() {
        RobotMessage m;
        while ((m = poll()) != null) {
            if (m.holds(MazeMessage.class)) {
                MazeMessage mm = m.as(MazeMessage.class);
                if (mm.sensed()) {
                    map.sensed(mm.x(), mm.y(), mm.open());
                }
                map.mate(mm.robot(), new MazeKnowledge.Mate(mm.x(), mm.y(), mm.nextX(), mm.nextY()));
                if (mm.gold() && finder == null) {
                    finder = mm.robot();
                }
            }
        }
    }

    private void tell(int nextX, int nextY, boolean gold) {
        broadcast(new MazeMessage(getName(), cx, cy, map.isSensed(cx, cy), openMask(cx, cy), nextX, nextY, gold));
    }

    private int openMask(int x, int y) {
        int mask = 0;
        for (int d = 0; d < 4; d++) {
            mask |= map.open(x, y, d) ? 1 << d : 0;
        }
        return mask;
    }

    private void decide() {
        if (pause > 0) {
            pause--;
            return;
        }
        if (!map.isSensed(cx, cy)) {
            map.sensed(cx, cy, WallSensing.openSides(this, laser, cellSize));
        }
        int d = choose();
        if (d < 0) {
            tell(-1, -1, false);
            pause = 10;
            return;
        }
        int nx = cx + Maze.DIRECTIONS[d][0];
        int ny = cy + Maze.DIRECTIONS[d][1];
        if (blockedBy(nx, ny) != null) {
            waitOrBackAway(d);
            return;
        }
        dir = d;
        waited = 0;
        tell(nx, ny, false);
        phase = Phase.ANNOUNCE;
    }

    /** The direction to take: the gold's heat first, then an unexplored neighbour, then a frontier. */
    private int choose() {
        int[] order = order();
        if (heat.senses()) {
            int d = Math.floorMod((int) Math.round((getTh() + heat.getBearing()) / 90), 4);
            if (map.open(cx, cy, d)) {
                return d;
            }
        }
        for (int d : order) {
            int nx = cx + Maze.DIRECTIONS[d][0];
            int ny = cy + Maze.DIRECTIONS[d][1];
            if (map.open(cx, cy, d) && !map.isSensed(nx, ny) && !map.claimedByMate(nx, ny)) {
                return d;
            }
        }
        Set<Long> avoid = new HashSet<>();
        for (String mate : map.mates()) {
            MazeKnowledge.Mate m = map.mate(mate);
            avoid.add(MazeKnowledge.key(m.x(), m.y()));
        }
        int d = map.towardsFrontier(cx, cy, order, avoid);
        return d >= 0 ? d : map.towardsFrontier(cx, cy, order, Set.of());
    }

    /** The four directions, starting at a seeded one, so teammates fan out differently. */
    private int[] order() {
        int first = random.nextInt(4);
        return new int[] {first, (first + 1) % 4, (first + 2) % 4, (first + 3) % 4};
    }

    /** The teammate that stands in the cell, or that claimed it and goes before this robot. */
    private String blockedBy(int x, int y) {
        String occupant = map.occupant(x, y);
        if (occupant != null) {
            return occupant;
        }
        for (String mate : map.mates()) {
            MazeKnowledge.Mate m = map.mate(mate);
            if (m.nextX() == x && m.nextY() == y && rankOf(mate) < rank) {
                return mate;
            }
        }
        return null;
    }

    private void waitOrBackAway(int wanted) {
        waited++;
        if (waited < PATIENCE * (1 + rank % 3)) {
            return;
        }
        // stuck: step into a free neighbour other than the one wanted, if there is one
        int[] order = order();
        for (int d : order) {
            int nx = cx + Maze.DIRECTIONS[d][0];
            int ny = cy + Maze.DIRECTIONS[d][1];
            if (d != wanted && map.open(cx, cy, d) && map.isSensed(cx, cy) && blockedBy(nx, ny) == null
                    && !map.claimedByMate(nx, ny)) {
                dir = d;
                waited = 0;
                tell(nx, ny, false);
                phase = Phase.ANNOUNCE;
                return;
            }
        }
        waited = 0;
    }

    private void announce() {
        int nx = cx + Maze.DIRECTIONS[dir][0];
        int ny = cy + Maze.DIRECTIONS[dir][1];
        if (blockedBy(nx, ny) != null) {
            phase = Phase.DECIDE;
            pause = 1;
            tell(-1, -1, false);
            return;
        }
        setHeading(dir * 90);
        phase = Phase.TURN;
    }

    private void turn() {
        if (isHeadingDone(0.5) && Math.abs(getRotVel()) < 1) {
            startX = getX();
            startY = getY();
            move(cellSize);
            phase = Phase.MOVE;
        }
    }

    private void drive() {
        if (isStalled()) {
            // something unexpected is in the way: go back to the centre of the cell it left
            double gone = Math.hypot(getX() - startX, getY() - startY);
            stop();
            move(-gone);
            phase = Phase.BACK;
            return;
        }
        if (isMoveDone(1) && isStopped()) {
            cx += Maze.DIRECTIONS[dir][0];
            cy += Maze.DIRECTIONS[dir][1];
            phase = Phase.DECIDE;
            map.sensed(cx, cy, WallSensing.openSides(this, laser, cellSize));
            tell(-1, -1, false);
        }
    }

    private void back() {
        if (isMoveDone(1) && isStopped()) {
            phase = Phase.DECIDE;
            pause = 5 + random.nextInt(10);
            tell(-1, -1, false);
        }
    }
}
