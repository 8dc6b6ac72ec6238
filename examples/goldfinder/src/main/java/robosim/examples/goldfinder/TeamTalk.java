package robosim.examples.goldfinder;

import static robosim.examples.goldfinder.MazeKnowledge.NONE;

import java.util.ArrayList;
import java.util.List;
import robosim.aria.ArRobot;
import robosim.hw.RobotMessage;

/**
 * What a Gold robot tells its team and what it hears from it, as {@link MazeMessage}s broadcast
 * through the Environment.
 *
 * <p>Told: where it is and the cells ahead it holds, the frontier it claimed or follows, the cell it
 * waits for, whether it found the gold, and some of the cells it sensed: the newest ones, then old
 * ones in turn, so a lost message costs time, never knowledge. It tells whenever what it says of
 * itself changes and, while nothing changes, every {@value #HEARTBEAT} steps.
 *
 * <p>Heard: every teammate's cells join the robot's map, and what each says of itself is kept; a
 * teammate not heard for a while is taken to stand where it last was, its move and claim lapsed.
 */
final class TeamTalk {
    /** Steps between the reports a robot repeats while nothing changes. */
    static final int HEARTBEAT = 10;
    /** How many of its sensed cells a report carries: the newest half, and old ones in turn. */
    private static final int CELLS_PER_REPORT = 16;

    private final ArRobot robot;
    private final MazeKnowledge map;
    private final List<int[]> ownCells;
    private final Course course;
    /** How many own cells the reports so far have carried as new. */
    private int reported;
    /** Which old cell the next report repeats, counted round the old ones. */
    private int repeatFrom;
    private long lastTold = Long.MIN_VALUE / 2;
    /** The step at which it tells its last change once more, so one lost message does not lose it. */
    private long repeatAt = -1;
    /** What its last report said of the robot itself. */
    private List<Long> lastSaid = List.of();

    /**
     * @param robot    the robot that talks
     * @param map      its map, which what it hears joins
     * @param ownCells the cells it sensed itself, in order (read only: the reports repeat them)
     * @param course   where it is and goes, which its reports say
     */
    TeamTalk(ArRobot robot, MazeKnowledge map, List<int[]> ownCells, Course course) {
        this.robot = robot;
        this.map = map;
        this.ownCells = ownCells;
        this.course = course;
    }

    /**
     * Reads every message that came: the cells join the map, each teammate's report of itself is
     * kept (a malformed report is ignored: its sender repeats its cells).
     *
     * @return the first robot heard to have found the gold, or null
     */
    String listen() {
        forgetSilentMates();
        String goldFinder = null;
        RobotMessage m;
        while ((m = robot.poll()) != null) {
            if (!m.holds(MazeMessage.class)) {
                continue;
            }
            MazeMessage mm;
            try {
                mm = m.as(MazeMessage.class);
            } catch (RuntimeException e) {
                continue;
            }
            hear(mm);
            if (mm.gold() && goldFinder == null) {
                goldFinder = mm.robot();
            }
        }
        return goldFinder;
    }

    private void hear(MazeMessage mm) {
        int[] c = mm.cells();
        for (int i = 0; i < c.length; i += 3) {
            if (!map.isSensed(c[i], c[i + 1])) {
                map.sensed(c[i], c[i + 1], c[i + 2]);
            }
        }
        if (!mm.robot().equals(robot.getName())) {
            List<Long> route = new ArrayList<>();
            for (int i = 0; i < mm.route().length; i += 2) {
                route.add(MazeKnowledge.key(mm.route()[i], mm.route()[i + 1]));
            }
            map.mate(mm.robot(), new MazeKnowledge.Mate(mm.x(), mm.y(), route,
                    mm.claim() ? mm.targetX() : NONE, mm.claim() ? mm.targetY() : NONE, robot.getStep(),
                    mm.wantX() == NONE ? -1 : MazeKnowledge.key(mm.wantX(), mm.wantY()),
                    mm.targetX() == NONE ? -1 : MazeKnowledge.key(mm.targetX(), mm.targetY())));
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
            if (robot.getStep() - m.heard() > TeamPlan.CLAIM_STEPS && (m.moving() || m.claims() || m.want() >= 0
                    || m.target() >= 0)) {
                map.mate(name, new MazeKnowledge.Mate(m.x(), m.y(), m.heard()));
            }
        }
    }

    /**
     * Tells the team where the robot is, what it holds and what it plans, when any of it has changed
     * since its last report (and once more at the next step, so that a lost message does not keep
     * a change from a teammate until the next heartbeat), or when it has said nothing for {@value
     * #HEARTBEAT} steps.
     */
    void tellIfChanged() {
        boolean changed = !said().equals(lastSaid);
        if (changed || robot.getStep() - lastTold >= HEARTBEAT || robot.getStep() == repeatAt) {
            tell(false);
            if (changed) {
                repeatAt = robot.getStep() + 1;
            }
        }
    }

    /** What a report would say of the robot itself, to see whether it changed. */
    private List<Long> said() {
        List<Long> out = new ArrayList<>(course.ahead());
        out.add(course.here());
        out.add(course.plan().target());
        out.add(course.plan().claim() ? 1L : 0L);
        out.add(course.want());
        return out;
    }

    /**
     * Broadcasts one report: where the robot is, the cells ahead it holds, its plan and wait from
     * its {@link Course}, and up to {@value #CELLS_PER_REPORT} of its own cells.
     *
     * @param gold whether it has found the gold
     */
    void tell(boolean gold) {
        TeamPlan.Plan plan = course.plan();
        long want = course.want();
        long t = plan.target();
        List<Long> ahead = course.ahead();
        int[] route = new int[2 * Math.min(ahead.size(), MazeMessage.MOST_AHEAD)];
        for (int i = 0; i < route.length / 2; i++) {
            route[2 * i] = MazeKnowledge.keyX(ahead.get(i));
            route[2 * i + 1] = MazeKnowledge.keyY(ahead.get(i));
        }
        robot.broadcast(new MazeMessage(robot.getName(), course.x(), course.y(), route,
                t < 0 ? NONE : plan.x(), t < 0 ? NONE : plan.y(), plan.claim(),
                want < 0 ? NONE : MazeKnowledge.keyX(want), want < 0 ? NONE : MazeKnowledge.keyY(want),
                cellsToRepeat(), gold));
        lastTold = robot.getStep();
        lastSaid = said();
    }

    /**
     * The cells a report carries: the ones sensed since the last report (up to half the report),
     * then old ones in turn, three numbers each.
     */
    private int[] cellsToRepeat() {
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
        return cells;
    }
}
