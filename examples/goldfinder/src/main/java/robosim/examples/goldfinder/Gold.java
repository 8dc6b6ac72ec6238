package robosim.examples.goldfinder;

import static robosim.examples.goldfinder.MazeKnowledge.NONE;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
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
 * and rear sonars ({@link WallSensing}), then drives one cell towards the frontier it has claimed
 * ({@link TeamPlan}): the nearest cell nobody has sensed that no nearer teammate has claimed. Every
 * few steps it tells its team ({@link MazeMessage}) where it is, where it drives, what it claimed
 * and which walls it sensed, so the team divides the maze: each branch taken by one robot is
 * removed from everyone's search. Claims that are not repeated lapse, so lost messages and a
 * teammate that fails leave no branch unexplored.
 *
 * <p>A robot never drives into a cell a teammate stands in or drives into. It steps aside for a
 * teammate that waits for its cell when it has nothing better to do, or when both wait for each
 * other and it has the higher number; it steps off the teammate's way to its target.
 *
 * <p>A heat sensor with a 360° view guides it: when the gold's heat is sensed through an open side,
 * that side is taken first. The robot has found the gold when its heat sensor places the gold
 * within {@value #FOUND_DISTANCE} mm; it reports the find to the Environment and broadcasts it,
 * and every teammate that hears it stops.
 */
public class Gold extends ArRobot {
    /** The gold is found when the heat sensor places it this near, mm. */
    public static final double FOUND_DISTANCE = 1000;
    /** The world property the maze's cell size, mm, is read from: {@code bin/robosim maze} writes it. */
    public static final String CELL_SIZE_PROPERTY = "cellSize";
    /** Steps between the reports a robot repeats while nothing changes. */
    static final int HEARTBEAT = 10;
    /** How many of its sensed cells a report carries: the newest half, and old ones in turn. */
    private static final int CELLS_PER_REPORT = 16;
    /** Steps a robot waits for a cell before it tries another way out. */
    private static final int PATIENCE = 60;
    /** The longest a robot tries to turn, steps (a quarter turn takes about 20). */
    private static final int TURN_STEPS = 80;
    /** The room a robot leaves before an echo ahead, mm. */
    private static final double CLEARANCE = 100;
    /** The longest a robot tries to back off an obstacle, steps. */
    private static final int BACK_STEPS = 60;
    /** The fewest steps between two drawings. */
    static final int DRAW_EVERY = 10;
    /** The most cells a robot drives in one move. */
    static final int LONGEST_RUN = 8;

    private enum Phase { DECIDE, ANNOUNCE, TURN, MOVE, BACK, DONE }

    private final int rank;
    /** The maze's cell size, mm: the world's, known once connected. */
    private double cellSize;
    private SplittableRandom random;
    private final MazeKnowledge map = new MazeKnowledge();
    private final ArSick laser = new ArSick();
    private ArHeatSensor heat;
    /** The cells this robot sensed itself, in order: what its reports repeat. */
    private final List<int[]> ownCells = new ArrayList<>();
    private int repeatFrom;
    private int reported;
    private Phase phase = Phase.DECIDE;
    private int cx;
    private int cy;
    private int dir = -1;
    /** Cells the current move crosses, in direction {@link #dir}. */
    private int runCells = 1;
    /** Whether the robot read the cells ahead since it last turned. */
    private boolean lookedAhead;
    private TeamPlan.Plan plan = TeamPlan.Plan.NONE;
    private long want = -1;
    private int waited;
    private int pause;
    private long lastTold = Long.MIN_VALUE / 2;
    /** When it last drew, what it drew: its own cells' count, its target and the cell it drew it from. */
    private long drawnAt = Long.MIN_VALUE / 2;
    private int drawnCells;
    private int drawnKnown;
    private long drawnTarget = -1;
    private long drawnFrom = -1;
    /** The step the robot began to back off an obstacle, and to turn. */
    private long backSince;
    private long turnSince;
    private String finder;

    /**
     * A Gold robot as the original's robot applications make one: the maze's cell size comes from
     * the world (its {@value #CELL_SIZE_PROPERTY} property, in the Environment's
     * welcome) and the seed of its tie-breaks from the run's seed, once it has connected.
     *
     * @param name the robot's name, {@code r<number>}: lower numbers go first where robots meet
     * @param host the Environment's host
     * @param port its robot port
     */
    public Gold(String name, String host, int port) {
        super(name, host, port, "p3dx");
        this.rank = rankOf(name);
        addRangeDevice(laser);
    }

    /**
     * @param name a robot's name
     * @return its number: the digits in its name, or a number made from the name if it has none
     */
    static int rankOf(String name) {
        String digits = name.replaceAll("\\D", "");
        if (digits.isEmpty() || digits.length() > 9) {
            return Math.abs(name.hashCode() % 1000);
        }
        return Integer.parseInt(digits);
    }

    /**
     * Runs one Gold robot, the original's way: {@code java robosim.examples.goldfinder.Gold
     * robotName host port}.
     *
     * @param args NAME HOST PORT
     */
    public static void main(String[] args) {
        run(args, "Gold");
    }

    /**
     * Connects one Gold robot named by the command line, searches, disconnects.
     *
     * @param args    NAME HOST PORT
     * @param program the program's name, for the usage line
     */
    static void run(String[] args, String program) {
        if (args.length != 3) {
            System.err.println("usage: " + program + " robotName host port");
            System.exit(2);
        }
        int port;
        try {
            port = Integer.parseInt(args[2]);
        } catch (NumberFormatException e) {
            System.err.println(program + ": '" + args[2] + "' was supplied for port: it must be a whole number, 1 to 65535");
            System.exit(2);
            return;
        }
        Gold robot = new Gold(args[0], args[1], port);
        if (!robot.blockingConnect()) {
            System.err.println(program + ": robot " + args[0] + " could not connect: " + robot.getConnectionError());
            System.exit(1);
        }
        try {
            robot.search();
        } catch (IllegalStateException e) {
            System.err.println(program + ": " + e.getMessage());
            robot.disconnect();
            System.exit(1);
        }
        robot.disconnect();
    }

    /**
     * Enables the motors (a Pioneer's are disabled when its program connects, as in ARIA), then
     * searches until the gold is found (by anyone) or the run ends; then stands still until the end.
     *
     * @throws IllegalStateException if the world gives no cell size, or one under 1000 mm
     */
    public void search() {
        cellSize = getWorldNumber(CELL_SIZE_PROPERTY).orElseThrow(() -> new IllegalStateException(
                "robot " + getName() + ": world gives no " + CELL_SIZE_PROPERTY
                        + " property; GoldFinder needs the maze's cell size, mm (see robosim maze)"));
        if (!(cellSize >= 1000)) {
            throw new IllegalStateException("robot " + getName() + ": the world's " + CELL_SIZE_PROPERTY
                    + " is " + cellSize + ": GoldFinder's mazes have cells of at least 1000 mm");
        }
        random = new SplittableRandom(getRunSeed() * 31 + rank);
        heat = new ArHeatSensor(360, 3 * cellSize);
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
            tell(NONE, NONE, true);
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
        if (getStep() - lastTold >= HEARTBEAT) {
            tellWhereIAm();
        }
        drawWhatItKnows();
    }

    /**
     * Draws, for viewers that show robots' drawings, what {@link TeamDrawings} makes of what this
     * robot knows. A layer is sent again only when it changed, at most every {@value #DRAW_EVERY}
     * steps.
     */
    private void drawWhatItKnows() {
        if (getStep() - drawnAt < DRAW_EVERY) {
            return;
        }
        if (ownCells.size() != drawnCells) {
            drawnCells = ownCells.size();
            draw(TeamDrawings.EXPLORED, TeamDrawings.explored(ownCells, cellSize));
            drawnAt = getStep();
        }
        if (map.sensedCount() != drawnKnown) {
            // what teammates told counts too: each robot's known map shows what reached it
            drawnKnown = map.sensedCount();
            draw(TeamDrawings.KNOWN, TeamDrawings.known(map, rank, cellSize));
            drawnAt = getStep();
        }
        long target = plan.target();
        if (target != drawnTarget || (target >= 0 && MazeKnowledge.key(cx, cy) != drawnFrom)) {
            drawnTarget = target;
            drawnFrom = MazeKnowledge.key(cx, cy);
            draw(TeamDrawings.CLAIM, TeamDrawings.claim(map, cx, cy, plan, cellSize));
            drawnAt = getStep();
        }
    }

    private void listen() {
        forgetSilentMates();
        RobotMessage m;
        while ((m = poll()) != null) {
            if (!m.holds(MazeMessage.class)) {
                continue;
            }
            MazeMessage mm;
            try {
                mm = m.as(MazeMessage.class);
            } catch (RuntimeException e) {
                continue; // a malformed report is ignored: the sender repeats its cells
            }
            int[] c = mm.cells();
            for (int i = 0; i < c.length; i += 3) {
                if (!map.isSensed(c[i], c[i + 1])) {
                    map.sensed(c[i], c[i + 1], c[i + 2]);
                }
            }
            if (!mm.robot().equals(getName())) {
                map.mate(mm.robot(), new MazeKnowledge.Mate(mm.x(), mm.y(), mm.nextX(), mm.nextY(),
                        mm.claim() ? mm.targetX() : NONE, mm.claim() ? mm.targetY() : NONE, getStep(),
                        mm.wantX() == NONE ? -1 : MazeKnowledge.key(mm.wantX(), mm.wantY()),
                        mm.targetX() == NONE ? -1 : MazeKnowledge.key(mm.targetX(), mm.targetY())));
            }
            if (mm.gold() && finder == null) {
                finder = mm.robot();
            }
        }
    }

    /**
     * A teammate not heard for {@link TeamPlan#CLAIM_STEPS} steps (its messages are lost, or it has
     * failed) is taken to stand where it last said it was: its move, its claim and its wait lapse,
     * so that no cell or frontier stays reserved for a robot that may never come.
     */
    private void forgetSilentMates() {
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if (getStep() - m.heard() > TeamPlan.CLAIM_STEPS && (m.moving() || m.claims() || m.want() >= 0
                    || m.target() >= 0)) {
                map.mate(name, new MazeKnowledge.Mate(m.x(), m.y(), m.heard()));
            }
        }
    }

    private void tellWhereIAm() {
        boolean moving = phase == Phase.ANNOUNCE || phase == Phase.TURN || phase == Phase.MOVE;
        if (moving && dir >= 0) {
            tell(cx + runCells * Directions.dx(dir), cy + runCells * Directions.dy(dir), false);
        } else {
            tell(NONE, NONE, false);
        }
    }

    private void tell(int nextX, int nextY, boolean gold) {
        int newest = Math.min(ownCells.size() - reported, CELLS_PER_REPORT / 2);
        List<int[]> send = new ArrayList<>(ownCells.subList(ownCells.size() - Math.max(newest, 0), ownCells.size()));
        reported = ownCells.size();
        int older = ownCells.size() - send.size();
        for (int i = 0; i < CELLS_PER_REPORT - send.size() && older > 0 && i < older; i++) {
            send.add(ownCells.get(repeatFrom % older));
            repeatFrom++;
        }
        int[] cells = new int[send.size() * 3];
        for (int i = 0; i < send.size(); i++) {
            System.arraycopy(send.get(i), 0, cells, 3 * i, 3);
        }
        long t = plan.target();
        broadcast(new MazeMessage(getName(), cx, cy, nextX, nextY, t < 0 ? NONE : plan.x(), t < 0 ? NONE : plan.y(),
                plan.claim(), want < 0 ? NONE : MazeKnowledge.keyX(want), want < 0 ? NONE : MazeKnowledge.keyY(want),
                cells, gold));
        lastTold = getStep();
    }

    private void senseHere() {
        int open = WallSensing.openSides(this, laser, cellSize);
        map.sensed(cx, cy, open);
        ownCells.add(new int[] {cx, cy, open});
    }

    /**
     * Reads the cells straight ahead with the laser ({@link WallSensing#cellsAhead}), so that a
     * corridor is driven through in one move instead of a stop in every cell.
     *
     * @return how many cells it sensed that nobody had
     */
    private int lookAhead() {
        int d = Math.floorMod((int) Math.round(getTh() / 90), 4);
        int[] ahead = WallSensing.cellsAhead(this, laser, cellSize);
        int added = 0;
        for (int j = 0; j < ahead.length; j++) {
            int x = cx + (j + 1) * Directions.dx(d);
            int y = cy + (j + 1) * Directions.dy(d);
            if (!map.isSensed(x, y)) {
                map.sensed(x, y, ahead[j]);
                ownCells.add(new int[] {x, y, ahead[j]});
                added++;
            }
        }
        return added;
    }

    private void decide() {
        if (pause > 0) {
            pause--;
            return;
        }
        if (!map.isSensed(cx, cy)) {
            senseHere();
        }
        lookAhead();
        int[] order = order();
        plan = TeamPlan.plan(map, rank, cx, cy, order, getStep());
        long goldCell = goldCell();
        if (goldCell >= 0 && goldCell != MazeKnowledge.key(cx, cy)
                && map.reach(cx, cy, order, Set.of()).containsKey(goldCell)) {
            plan = new TeamPlan.Plan(goldCell, true); // the heat places the gold in a cell known to be reachable
        }
        int d = goldCell >= 0 && plan.target() == goldCell ? -1 : heatDirection();
        if (d < 0 && plan.target() >= 0) {
            d = TeamPlan.firstStep(map, cx, cy, plan.target(), order);
            if (d >= 0 && !plan.claim()
                    && MazeKnowledge.key(cx + Directions.dx(d), cy + Directions.dy(d)) == plan.target()) {
                d = -1; // following: the frontier itself is the claimant's to enter
            }
        }
        String waiting = waitedForBy();
        if (waiting != null && (d < 0 || !plan.claim() || mutual(waiting, d) || waited > PATIENCE / 2)) {
            if (stepAside(waiting)) {
                return;
            }
        }
        if (d < 0) {
            idle();
            return;
        }
        int nx = cx + Directions.dx(d);
        int ny = cy + Directions.dy(d);
        if (map.holder(nx, ny) != null) {
            waitFor(nx, ny, d);
            return;
        }
        go(d, run(d, plan.target(), order));
    }

    /**
     * How many cells to drive straight in one move, without stopping: on along the way to the
     * target while it keeps direction {@code d} through cells already sensed that no teammate
     * holds, up to {@value #LONGEST_RUN}; a cell nobody has sensed ends the run (it must be sensed
     * from its centre).
     */
    private int run(int d, long target, int[] order) {
        if (target < 0 || heatDirection() >= 0) {
            return 1;
        }
        List<Long> path = map.path(cx, cy, MazeKnowledge.keyX(target), MazeKnowledge.keyY(target), order, map.held());
        int cells = 1;
        while (cells < path.size() && cells < LONGEST_RUN) {
            long here = path.get(cells - 1);
            long next = path.get(cells);
            if (!map.isSensed(MazeKnowledge.keyX(here), MazeKnowledge.keyY(here))
                    || MazeKnowledge.keyX(next) - MazeKnowledge.keyX(here) != Directions.dx(d)
                    || MazeKnowledge.keyY(next) - MazeKnowledge.keyY(here) != Directions.dy(d)
                    || (!plan.claim() && next == target)) {
                break;
            }
            cells++;
        }
        return path.isEmpty() || path.get(0) != MazeKnowledge.key(cx + Directions.dx(d), cy + Directions.dy(d))
                ? 1 : cells;
    }

    private void idle() {
        want = -1;
        waited = 0;
        tell(NONE, NONE, false);
        pause = 5;
    }

    private void go(int d, int cells) {
        dir = d;
        runCells = cells;
        want = -1;
        waited = 0;
        tell(cx + cells * Directions.dx(d), cy + cells * Directions.dy(d), false);
        lookedAhead = false;
        phase = Phase.ANNOUNCE;
    }

    /**
     * The cell where the heat sensor places the gold, or -1 while it senses no heat. (A robot can
     * know a cell from afar, read with its laser: the heat brings it there.)
     */
    private long goldCell() {
        if (!heat.senses()) {
            return -1;
        }
        double bearing = Math.toRadians(getTh() + heat.getBearing());
        double gx = getX() + heat.getDistance() * Math.cos(bearing);
        double gy = getY() + heat.getDistance() * Math.sin(bearing);
        return MazeKnowledge.key((int) Math.floor(gx / cellSize), (int) Math.floor(gy / cellSize));
    }

    /**
     * The side towards the gold's heat, if the heat is sensed through an open side onto a cell
     * nobody has sensed; else -1. (Heat passes through walls: a known cell towards it may lead
     * nowhere near the gold.)
     */
    private int heatDirection() {
        if (!heat.senses()) {
            return -1;
        }
        int d = Math.floorMod((int) Math.round((getTh() + heat.getBearing()) / 90), 4);
        return map.open(cx, cy, d) && !map.isSensed(cx + Directions.dx(d), cy + Directions.dy(d)) ? d : -1;
    }

    /** The four directions, starting at a seeded one, so teammates fan out differently. */
    private int[] order() {
        int first = random.nextInt(4);
        return new int[] {first, (first + 1) % 4, (first + 2) % 4, (first + 3) % 4};
    }

    /** A teammate that waits to enter this robot's cell, or null. */
    private String waitedForBy() {
        long here = MazeKnowledge.key(cx, cy);
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if (m.want() == here && getStep() - m.heard() <= 3 * HEARTBEAT) {
                return name;
            }
        }
        return null;
    }

    /** Whether this robot wants the waiting teammate's cell and gives way to it by number. */
    private boolean mutual(String mate, int d) {
        MazeKnowledge.Mate m = map.mate(mate);
        return m != null && m.x() == cx + Directions.dx(d) && m.y() == cy + Directions.dy(d)
                && rankOf(mate) < rank;
    }

    private void waitFor(int nx, int ny, int d) {
        long k = MazeKnowledge.key(nx, ny);
        if (want != k) {
            want = k;
            waited = 0;
            tell(NONE, NONE, false);
        }
        waited++;
        if (waited >= PATIENCE * (1 + rank % 3)) {
            // stuck: any free open side other than the one wanted, then think again
            for (int s : order()) {
                int sx = cx + Directions.dx(s);
                int sy = cy + Directions.dy(s);
                if (s != d && map.open(cx, cy, s) && map.isSensed(sx, sy) && map.holder(sx, sy) == null) {
                    go(s, 1);
                    return;
                }
            }
            waited = 0;
        }
    }

    /**
     * Drives off a teammate's way: to the nearest cell that is neither on the teammate's path to
     * its target nor held by anyone, one cell at a time.
     *
     * @return whether a way aside was found and taken
     */
    private boolean stepAside(String mate) {
        MazeKnowledge.Mate m = map.mate(mate);
        if (m == null) {
            return false;
        }
        Set<Long> onItsWay = new HashSet<>();
        onItsWay.add(MazeKnowledge.key(cx, cy));
        long target = m.target();
        if (target >= 0) {
            onItsWay.addAll(map.path(m.x(), m.y(), MazeKnowledge.keyX(target), MazeKnowledge.keyY(target),
                    new int[] {0, 1, 2, 3}, Set.of()));
        }
        Set<Long> held = map.held();
        Map<Long, MazeKnowledge.Reach> reach = map.reach(cx, cy, order(), held);
        long best = -1;
        int bestCells = Integer.MAX_VALUE;
        for (Map.Entry<Long, MazeKnowledge.Reach> e : reach.entrySet()) {
            long k = e.getKey();
            if (onItsWay.contains(k) || !map.sensedCells().contains(k) || e.getValue().cells() == 0) {
                continue;
            }
            if (e.getValue().cells() < bestCells || (e.getValue().cells() == bestCells && k < best)) {
                best = k;
                bestCells = e.getValue().cells();
            }
        }
        if (best < 0) {
            return false;
        }
        go(reach.get(best).first(), 1);
        return true;
    }

    private void announce() {
        boolean contested = false;
        for (int k = 1; k <= runCells; k++) {
            contested |= contested(cx + k * Directions.dx(dir), cy + k * Directions.dy(dir));
        }
        if (contested) {
            phase = Phase.DECIDE;
            pause = 1;
            tell(NONE, NONE, false);
            return;
        }
        setHeading(dir * 90);
        turnSince = getStep();
        phase = Phase.TURN;
    }

    /** Whether a teammate stands in the cell, or drives into it and goes before this robot. */
    private boolean contested(int x, int y) {
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if ((m.x() == x && m.y() == y) || (m.nextX() == x && m.nextY() == y && rankOf(name) < rank)) {
                return true;
            }
        }
        return false;
    }

    private void turn() {
        if (getStep() - turnSince > TURN_STEPS) {
            // something keeps the robot from turning (a teammate pressed against it): think again
            stop();
            phase = Phase.DECIDE;
            pause = 5 + random.nextInt(10);
            tell(NONE, NONE, false);
            return;
        }
        if (isHeadingDone(0.5) && Math.abs(getRotVel()) < 1) {
            if (!lookedAhead) {
                lookedAhead = true;
                if (lookAhead() > 0) {
                    phase = Phase.DECIDE; // what it saw may change the way
                    return;
                }
            }
            // the laser has the last word: a teammate the messages have not told of may stand ahead
            runCells = Math.min(runCells, clearCellsAhead());
            if (runCells == 0) {
                phase = Phase.DECIDE;
                pause = 5 + random.nextInt(10);
                tell(NONE, NONE, false);
                return;
            }
            // to the far cell's centre, measured from where the robot is: a start off the centre is made good
            move(along(cx + runCells * Directions.dx(dir), cy + runCells * Directions.dy(dir)));
            phase = Phase.MOVE;
        }
    }

    private void drive() {
        if (isStalled()) {
            // something unexpected is in the way: back to the centre of the last cell it drove through
            stop();
            int dx = Directions.dx(dir);
            int dy = Directions.dy(dir);
            int crossed = (int) Math.floor(along(cx, cy) / -cellSize);
            crossed = Math.max(0, Math.min(runCells - 1, crossed));
            cx += crossed * dx;
            cy += crossed * dy;
            move(along(cx, cy));
            backSince = getStep();
            phase = Phase.BACK;
            tell(NONE, NONE, false);
            return;
        }
        if (isMoveDone(1) && isStopped()) {
            cx += runCells * Directions.dx(dir);
            cy += runCells * Directions.dy(dir);
            phase = Phase.DECIDE;
            if (!map.isSensed(cx, cy)) {
                senseHere();
            }
            tell(NONE, NONE, false);
        }
    }

    /**
     * How many cells ahead the robot can drive into, by its laser's beam straight ahead: the echo
     * must lie beyond the far cell's centre by the robot's front and a margin.
     */
    private int clearCellsAhead() {
        int[] scan = laser.getRawScan();
        if (scan.length == 0) {
            return runCells;
        }
        double reach = scan[scan.length / 2] + getParameters().laserX();
        double front = getParameters().robotLengthFront() + CLEARANCE;
        int cells = 0;
        while (cells < runCells && along(cx + (cells + 1) * Directions.dx(dir), cy + (cells + 1) * Directions.dy(dir))
                + front <= reach) {
            cells++;
        }
        return cells;
    }

    /**
     * The signed distance, along the robot's direction of travel, from where it is to a cell's
     * centre: negative when the centre lies behind.
     */
    private double along(int x, int y) {
        return ((x + 0.5) * cellSize - getX()) * Directions.dx(dir)
                + ((y + 0.5) * cellSize - getY()) * Directions.dy(dir);
    }

    private void back() {
        boolean blocked = isStalled() || getStep() - backSince > BACK_STEPS;
        if ((isMoveDone(1) && isStopped()) || blocked) {
            // blocked again (a teammate came up behind): stop where it is; the next move makes good the offset
            stop();
            phase = Phase.DECIDE;
            pause = 5 + random.nextInt(10);
            tell(NONE, NONE, false);
        }
    }
}
