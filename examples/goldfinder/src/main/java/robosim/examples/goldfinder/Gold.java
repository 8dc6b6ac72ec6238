package robosim.examples.goldfinder;

import java.util.SplittableRandom;
import robosim.aria.ArHeatSensor;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;
import robosim.aria.ArUtil;

/**
 * A Pioneer that searches a grid maze for gold by its sensors alone, with its team. Start reading
 * here: this class is the robot's loop, and each part of what it does has a class of its own.
 *
 * <p>It senses as it drives: every step its laser reads the sides of the cells around it ({@link
 * Survey}, {@link WallSensing}), and it keeps what it and its teammates sensed ({@link
 * MazeKnowledge}, the map it believes). It claims the nearest frontier, a cell nobody has sensed,
 * that no nearer teammate has claimed ({@link TeamPlan}), and drives there without stopping from
 * cell to cell, taking each bend as an arc ({@link Track}, {@link Driving}); it commits to the
 * next cell of its way only when it must, so what it has just sensed and heard still chooses the
 * way ({@link Wayfinder}, {@link SearchPhases}). It tells its team ({@link TeamTalk}, by {@link
 * MazeMessage}) where it is, the cells ahead it has committed to, what it claimed and which walls
 * it sensed, whenever that changes and every few steps, so the team divides the maze: each branch
 * taken by one robot is removed from everyone's search. Claims that are not repeated lapse, so
 * lost messages and a teammate that fails leave no branch unexplored. Viewers can show what it
 * believes ({@link TeamDrawings}).
 *
 * <p>A robot never drives into a cell a teammate has committed to, nor into one a teammate stands
 * in unless that teammate is leaving it the other way (then it follows, and its laser keeps the
 * distance). Where it must wait it stops at a cell's centre; it steps aside for a teammate that
 * waits for its cell when it has nothing better to do, or when both wait for each other and it
 * has the higher number; it steps off the teammate's way to its target.
 *
 * <p>A heat sensor with a 360° view guides it at the end ({@link HeatGuide}): walls block heat, so
 * once it feels the gold the gold is in sight, and it heads for the gold's cell (or, if no way
 * there is known yet, for the frontier nearest it). The robot has found the gold when its heat
 * sensor places the gold within {@value #FOUND_DISTANCE} mm; it reports the find to the
 * Environment and broadcasts it, and every teammate that hears it stops.
 *
 * <p>For experiments it reports one metric of its own, {@value #CELLS_SENSED}: how many cells its
 * laser has read, each time that grows (the team's sum, against the maze's cells, is how much of the
 * maze the search had to see).
 */
public class Gold extends ArRobot {
    /** The gold is found when the heat sensor places it this near, mm. */
    public static final double FOUND_DISTANCE = 1000;
    /** The world property the maze's cell size, mm, is read from: {@code bin/robosim maze} writes it. */
    public static final String CELL_SIZE_PROPERTY = "cellSize";
    /** The metric it reports: the cells it has sensed itself. */
    public static final String CELLS_SENSED = "cellsSensed";

    private final int rank;
    private final ArSick laser = new ArSick();
    /** What it believes of the maze and of its teammates. */
    private final MazeKnowledge map = new MazeKnowledge();
    /** Its parts, made once it has connected and knows the maze's cell size. */
    private TeamTalk team;
    private HeatGuide heat;
    private SearchPhases phases;
    private TeamDrawings drawings;
    private Survey survey;
    /** The cells sensed when it last reported them. */
    private int cellsReported;
    /** Who found the gold, as far as this robot knows, or null. */
    private String finder;

    /**
     * A Gold robot as the original's robot applications make one: the maze's cell size comes from
     * the world (its {@value #CELL_SIZE_PROPERTY} property, in the Environment's welcome) and the
     * seed of its tie-breaks from the run's seed, once it has connected.
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
     * Enables the motors (a Pioneer's are disabled when its program connects, as in ARIA), then
     * searches until the gold is found (by anyone) or the run ends; then stands still until the end.
     *
     * @throws IllegalStateException if the world gives no cell size, or one under 1000 mm
     */
    public void search() {
        double cellSize = worldCellSize();
        SplittableRandom random = new SplittableRandom(getRunSeed() * 31 + rank);
        ArHeatSensor heatSensor = new ArHeatSensor(360, 3 * cellSize);
        enableMotors();
        laser.blockingConnect();
        heatSensor.attach(this);
        makeParts(cellSize, random, heatSensor);
        ArUtil.sleep(getStepMs());
        while (isConnected()) {
            cycle();
            ArUtil.sleep(getStepMs());
        }
    }

    /**
     * One step of the robot's loop: hear the team; stop if anyone has found the gold, or report the
     * find when the heat places the gold near; else take the search one phase further, tell the
     * team where it is if it has said nothing for a while, and draw what it believes.
     */
    void cycle() {
        String heardFinder = team.listen();
        if (finder == null) {
            finder = heardFinder;
        }
        if (phases.done()) {
            return;
        }
        if (finder != null) {
            stop();
            phases.end();
            return;
        }
        if (heat.placesGoldWithin(FOUND_DISTANCE)) {
            reportTheFind();
            return;
        }
        phases.step();
        int sensed = survey.ownCells().size();
        if (sensed != cellsReported) {
            reportMetric(CELLS_SENSED, sensed);
            cellsReported = sensed;
        }
        team.tellIfChanged();
        drawings.update();
    }

    /** Stops, reports the find to the Environment, tells the team and says so; the search is over. */
    private void reportTheFind() {
        finder = getName();
        long foundStep = getStep();
        stop();
        reportFound("gold");
        team.tell(true);
        say("found the gold at step " + foundStep);
        phases.end();
    }

    /** @return who found the gold, as far as this robot knows, or null */
    public String getFinder() {
        return finder;
    }

    /** The maze's cell size, from the world: at least 1000 mm. */
    private double worldCellSize() {
        double cellSize = getWorldNumber(CELL_SIZE_PROPERTY).orElseThrow(() -> new IllegalStateException(
                "robot " + getName() + ": world gives no " + CELL_SIZE_PROPERTY
                        + " property; GoldFinder needs the maze's cell size, mm (see robosim maze)"));
        if (!(cellSize >= 1000)) {
            throw new IllegalStateException("robot " + getName() + ": the world's " + CELL_SIZE_PROPERTY
                    + " is " + cellSize + ": GoldFinder's mazes have cells of at least 1000 mm");
        }
        return cellSize;
    }

    /** Makes the robot's parts, which share its map and its course, starting in the cell it stands in. */
    private void makeParts(double cellSize, SplittableRandom random, ArHeatSensor heatSensor) {
        Course course = new Course((int) Math.floor(getX() / cellSize), (int) Math.floor(getY() / cellSize));
        survey = new Survey(this, laser, cellSize, heatSensor.getMaxRange(), map, course);
        team = new TeamTalk(this, map, survey.ownCells(), course);
        heat = new HeatGuide(this, heatSensor, cellSize);
        Wayfinder way = new Wayfinder(this, rank, map, course, heat, random);
        Driving driving = new Driving(this, laser);
        phases = new SearchPhases(this, cellSize, survey, way, driving, map, course, random);
        drawings = new TeamDrawings(this, rank, cellSize, map, survey.ownCells(), course);
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
}
