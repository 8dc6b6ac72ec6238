package robosim.experiment;

import java.util.ArrayList;
import java.util.DoubleSummaryStatistics;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;
import robosim.env.world.World;
import robosim.experiment.Experiment.Aggregate;

/**
 * The metrics of a run: the built-in ones, from the run's report, and those its programs reported.
 * Every metric but {@value #WALL_TIME} is the simulation's own, the same for the same run wherever
 * and however fast it runs.
 */
public final class Metrics {
    /** A metric's name. */
    public static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_.-]{0,63}");

    /** Steps simulated. */
    public static final String STEPS = "steps";
    /** Simulated time, s. */
    public static final String SIM_TIME = "simTime";
    /** How the run ended, a short word. */
    public static final String ENDING = "ending";
    /** Why, in words. */
    public static final String END_REASON = "endReason";
    /** 1 if the world's gold was found, 0 if not; empty in a world without gold. */
    public static final String FOUND = "found";
    /** The step the gold was found at; empty if it was not. */
    public static final String FOUND_STEP = "foundStep";
    /** Who found it. */
    public static final String FOUND_BY = "foundBy";
    /** Steps no team could find the gold in fewer of, however well it knew the world ({@link robosim.env.world.maze.GoldBound}); empty without gold. */
    public static final String LOWER_BOUND = "lowerBound";
    /** The steps to find the gold over the lower bound: at least 1, and the nearer 1 the nearer a perfect search at top speed. */
    public static final String BOUND_RATIO = "boundRatio";
    /** The robots in the run. */
    public static final String ROBOTS = "robots";
    /** Distance travelled by all the robots, mm. */
    public static final String DISTANCE = "distance";
    /** Collisions of all the robots. */
    public static final String COLLISIONS = "collisions";
    /** Times a robot became stalled, all the robots'. */
    public static final String STALLS = "stalls";
    /** Messages the robots sent. */
    public static final String MESSAGES_SENT = "messagesSent";
    /** Copies of their messages lost on the way to a recipient (range, walls, the loss chance). */
    public static final String MESSAGES_LOST = "messagesLost";
    /** Wall-clock time of the run, s: the one metric that is the machine's, not the simulation's. */
    public static final String WALL_TIME = "wallTime";

    /** What a program's metric is called when its own name is another column's. */
    public static final String PROGRAM_PREFIX = "program.";

    /** The built-in metrics, in column order. */
    public static final List<String> BUILT_IN = List.of(STEPS, SIM_TIME, ENDING, FOUND, FOUND_STEP, FOUND_BY,
            LOWER_BOUND, BOUND_RATIO, ROBOTS, DISTANCE, COLLISIONS, STALLS, MESSAGES_SENT, MESSAGES_LOST, END_REASON, WALL_TIME);

    private Metrics() {
    }

    /**
     * @param report     the run's report
     * @param world      its world
     * @param lowerBound its maze's lower bound, or null
     * @param aggregates how the robots' reported values make the run's
     * @param wallTime   the run's wall-clock time, s
     * @param factors    the experiment's factors, whose columns a reported metric must not take
     * @return the run's metrics, built-in first
     */
    static Map<String, Object> of(RunReport report, World world, Long lowerBound, Map<String, Aggregate> aggregates,
                                  double wallTime, List<String> factors) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put(STEPS, report.steps());
        m.put(SIM_TIME, report.timeMs() / 1000.0);
        m.put(ENDING, report.ending().wireName());
        boolean gold = world.gold() != null;
        m.put(FOUND, gold ? (report.find() == null ? 0 : 1) : null);
        m.put(FOUND_STEP, report.find() == null ? null : report.find().step());
        m.put(FOUND_BY, report.find() == null ? null : report.find().robot());
        m.put(LOWER_BOUND, lowerBound);
        m.put(BOUND_RATIO, report.find() == null || lowerBound == null || lowerBound == 0 ? null
                : Math.round(report.find().step() * 10_000.0 / lowerBound) / 10_000.0);
        m.put(ROBOTS, report.robots().size());
        double distance = 0;
        long collisions = 0;
        long stalls = 0;
        long sent = 0;
        long lost = 0;
        for (RobotSummary r : report.robots()) {
            distance += r.distance();
            collisions += r.collisions();
            stalls += r.stalls();
            sent += r.messagesSent();
            lost += r.messagesLost();
        }
        m.put(DISTANCE, Math.round(distance * 10) / 10.0);
        m.put(COLLISIONS, collisions);
        m.put(STALLS, stalls);
        m.put(MESSAGES_SENT, sent);
        m.put(MESSAGES_LOST, lost);
        m.put(END_REASON, report.endReason());
        reported(report, aggregates).forEach((name, value) -> {
            // a program's metric never takes another column's name: it is kept as program.NAME instead
            boolean taken = BUILT_IN.contains(name) || factors.contains(name) || ResultsTable.RUN_COLUMNS.contains(name);
            m.put(taken ? PROGRAM_PREFIX + name : name, value);
        });
        m.put(WALL_TIME, Math.round(wallTime * 1000) / 1000.0);
        return m;
    }

    /**
     * The run's value of each metric the programs reported: the robots' values made one as the
     * experiment says ({@code aggregate}), their mean unless told.
     */
    private static Map<String, Double> reported(RunReport report, Map<String, Aggregate> aggregates) {
        Map<String, List<Double>> values = new LinkedHashMap<>();
        report.metrics().values().forEach(robot -> robot.forEach((name, v) ->
                values.computeIfAbsent(name, n -> new ArrayList<>()).add(v)));
        Map<String, Double> out = new LinkedHashMap<>();
        values.forEach((name, vs) -> {
            DoubleSummaryStatistics s = vs.stream().mapToDouble(Double::doubleValue).summaryStatistics();
            out.put(name, switch (aggregates.getOrDefault(name, Aggregate.MEAN)) {
                case MEAN -> s.getAverage();
                case SUM -> s.getSum();
                case MIN -> s.getMin();
                case MAX -> s.getMax();
            });
        });
        return out;
    }

    /**
     * @param report the run's report
     * @return each robot's figures
     */
    static List<RunRecord.RobotFigures> robots(RunReport report) {
        List<RunRecord.RobotFigures> out = new ArrayList<>();
        for (RobotSummary r : report.robots()) {
            Map<String, Object> f = new LinkedHashMap<>();
            f.put(DISTANCE, Math.round(r.distance() * 10) / 10.0);
            f.put(COLLISIONS, r.collisions());
            f.put(STALLS, r.stalls());
            f.put(MESSAGES_SENT, r.messagesSent());
            f.put(MESSAGES_LOST, r.messagesLost());
            f.put("messagesReceived", r.messagesReceived());
            f.putAll(report.metrics().getOrDefault(r.name(), Map.of()));
            out.add(new RunRecord.RobotFigures(r.name(), f));
        }
        return out;
    }
}
