package robosim.examples.goldfinder;

import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import robosim.aria.ArRobot;

/**
 * The rules by which a Gold robot chooses its way, a cell at a time: the side to leave its last
 * committed cell by (along the way to the gold's cell once the heat places it, else to the
 * frontier {@link TeamPlan} gives it), and how it keeps out of its teammates' way: it does not
 * come into a cell a teammate holds against it, waits for one (and after a while tries another way
 * out), steps aside for a teammate that waits for its cell, and gives up committed cells a
 * teammate has taken first. {@link SearchPhases} asks; the answers are sides of a cell, 0 to 3, or
 * -1 for none.
 */
final class Wayfinder {
    /** Steps a robot waits for a cell before it tries another way out. */
    private static final int PATIENCE = 60;

    private final ArRobot robot;
    private final int rank;
    private final MazeKnowledge map;
    private final Course course;
    private final HeatGuide heat;
    private final SplittableRandom random;

    /**
     * @param robot  the robot
     * @param rank   its number: lower numbers go first where robots meet
     * @param map    what it knows
     * @param course where it is and goes; the plan and the wait are set here
     * @param heat   its heat sensor's hints
     * @param random the robot's seeded tie-breaks
     */
    Wayfinder(ArRobot robot, int rank, MazeKnowledge map, Course course, HeatGuide heat, SplittableRandom random) {
        this.robot = robot;
        this.rank = rank;
        this.map = map;
        this.course = course;
        this.heat = heat;
        this.random = random;
    }

    /** The robot's direction order, for ways of equal length: drawn again in each cell it comes into. */
    private int[] order = {0, 1, 2, 3};

    /** Draws a new direction order, starting at a seeded side, so teammates fan out differently. */
    void newOrder() {
        int first = random.nextInt(4);
        order = new int[] {first, (first + 1) % 4, (first + 2) % 4, (first + 3) % 4};
    }

    /** @return the robot's direction order, for ways of equal length */
    int[] order() {
        return order.clone();
    }

    /**
     * Plans from the last cell the robot has committed to (the frontier to claim or follow, or the
     * gold's cell when the heat places it in a cell known to be reachable) and picks the side of
     * that cell to leave by: the first step towards the target. A robot that follows a teammate's
     * claim does not enter the frontier itself. While that cell is a frontier nobody has sensed yet,
     * no side is known to lead anywhere: there is none, and the plan stays as it was.
     *
     * @return the side, or -1 for none
     */
    int chooseSide() {
        long from = course.last();
        int x = MazeKnowledge.keyX(from);
        int y = MazeKnowledge.keyY(from);
        if (!map.isSensed(x, y)) {
            return -1; // it drives into a frontier: no way on is known until it is sensed; the plan stands
        }
        TeamPlan.Plan plan = TeamPlan.plan(map, rank, x, y, course.ahead().size(), order, robot.getStep());
        long goldCell = heat.goldCell();
        if (goldCell >= 0 && goldCell != from) {
            plan = towardsGold(x, y, goldCell, plan);
        }
        course.plan(plan);
        if (plan.target() < 0) {
            return -1;
        }
        int d = TeamPlan.firstStep(map, x, y, plan.target(), order);
        if (d >= 0 && !plan.claim()
                && MazeKnowledge.key(x + Directions.dx(d), y + Directions.dy(d)) == plan.target()) {
            return -1; // following: the frontier itself is the claimant's to enter
        }
        return d;
    }

    /**
     * The heat places the gold in a cell: head there if a way is known, else for the frontier
     * nearest it (by columns and rows, then by way), else keep the plan.
     */
    private TeamPlan.Plan towardsGold(int x, int y, long goldCell, TeamPlan.Plan plan) {
        Map<Long, MazeKnowledge.Reach> reach = map.reach(x, y, order, Set.of());
        if (reach.containsKey(goldCell)) {
            return new TeamPlan.Plan(goldCell, true);
        }
        long best = -1;
        int bestApart = Integer.MAX_VALUE;
        int bestCells = Integer.MAX_VALUE;
        for (Map.Entry<Long, MazeKnowledge.Reach> e : reach.entrySet()) {
            long f = e.getKey();
            if (map.isSensed(MazeKnowledge.keyX(f), MazeKnowledge.keyY(f))) {
                continue;
            }
            int apart = Math.abs(MazeKnowledge.keyX(f) - MazeKnowledge.keyX(goldCell))
                    + Math.abs(MazeKnowledge.keyY(f) - MazeKnowledge.keyY(goldCell));
            int cells = e.getValue().cells();
            if (apart < bestApart || (apart == bestApart && cells < bestCells)) {
                best = f;
                bestApart = apart;
                bestCells = cells;
            }
        }
        return best < 0 ? plan : new TeamPlan.Plan(best, true);
    }

    /**
     * @param meant the cells ahead the robot meant to drive through
     * @return the first teammate, by name, that stands in the robot's cell or one of those, or null
     */
    String blocker(List<Long> meant) {
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            long at = MazeKnowledge.key(m.x(), m.y());
            if (at == course.here() || meant.contains(at)) {
                return name;
            }
        }
        return null;
    }

    /** @return a teammate that waits to enter this robot's cell, or null */
    String waitedForBy() {
        long here = course.here();
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if (m.want() == here && robot.getStep() - m.heard() <= 3 * TeamTalk.HEARTBEAT) {
                return name;
            }
        }
        return null;
    }

    /**
     * Whether this robot makes way for a teammate that waits for its cell: when it has nowhere to go
     * or only follows, when it wants the teammate's cell and the teammate has the lower number, or
     * when it has waited itself a while.
     */
    boolean givesWayTo(String mate, int side) {
        return side < 0 || !course.plan().claim() || mutual(mate, side) || course.waited() > PATIENCE / 2;
    }

    /** Whether this robot wants the waiting teammate's cell and gives way to it by number. */
    private boolean mutual(String mate, int d) {
        MazeKnowledge.Mate m = map.mate(mate);
        return m != null && m.x() == course.x() + Directions.dx(d) && m.y() == course.y() + Directions.dy(d)
                && Gold.rankOf(mate) < rank;
    }

    /**
     * The way off a teammate's path: the first side towards the nearest cell that is neither on the
     * teammate's way to its target nor held by anyone.
     *
     * @return the side, or -1 if there is no such cell
     */
    int sideAside(String mate) {
        MazeKnowledge.Mate m = map.mate(mate);
        if (m == null) {
            return -1;
        }
        Set<Long> onItsWay = new HashSet<>();
        onItsWay.add(course.here());
        long target = m.target();
        if (target >= 0) {
            onItsWay.addAll(map.path(m.x(), m.y(), MazeKnowledge.keyX(target), MazeKnowledge.keyY(target),
                    new int[] {0, 1, 2, 3}, Set.of()));
        }
        Set<Long> held = map.held();
        Map<Long, MazeKnowledge.Reach> reach = map.reach(course.x(), course.y(), order, held);
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
        return best < 0 ? -1 : reach.get(best).first();
    }

    /** @return whether a teammate stands in the cell across {@code side} of the robot's, or has committed to it */
    boolean heldByTeammate(int side) {
        return map.heldAgainst(MazeKnowledge.key(course.x() + Directions.dx(side), course.y() + Directions.dy(side)),
                course.here());
    }

    /**
     * Waits one more step for the cell across {@code side}, which a teammate holds (telling the team
     * when the wait begins). After long enough, a number of steps that differs by robot, it takes
     * any other free open side towards a sensed cell, if there is one.
     *
     * @return the other side to take, or -1 to wait on
     */
    int waitFor(int side) {
        long k = MazeKnowledge.key(course.x() + Directions.dx(side), course.y() + Directions.dy(side));
        if (course.want() != k) {
            course.startWaiting(k);
        }
        course.waitOneStep();
        if (course.waited() >= PATIENCE * (1 + rank % 3)) {
            // stuck: any free open side other than the one wanted, then think again
            for (int s : order) {
                int sx = course.x() + Directions.dx(s);
                int sy = course.y() + Directions.dy(s);
                if (s != side && map.open(course.x(), course.y(), s) && map.isSensed(sx, sy)
                        && map.holder(sx, sy) == null) {
                    return s;
                }
            }
            course.restartPatience();
        }
        return -1;
    }

    /**
     * @return the index in the robot's committed cells of the first one that a teammate stands in,
     *         or has committed to and goes before this robot (a lower number), or -1
     */
    int firstContested() {
        List<Long> ahead = course.ahead();
        for (int k = 0; k < ahead.size(); k++) {
            int x = MazeKnowledge.keyX(ahead.get(k));
            int y = MazeKnowledge.keyY(ahead.get(k));
            for (String name : map.mates()) {
                MazeKnowledge.Mate m = map.mate(name);
                if ((m.x() == x && m.y() == y) || (m.route().contains(ahead.get(k)) && Gold.rankOf(name) < rank)) {
                    return k;
                }
            }
        }
        return -1;
    }
}
