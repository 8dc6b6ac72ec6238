package robosim.examples.goldfinder;

import static robosim.examples.goldfinder.MazeKnowledge.NONE;

import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import robosim.aria.ArRobot;

/**
 * The rules by which a Gold robot, standing at a cell's centre, chooses its way: the side to leave
 * by (towards the gold's heat, else along the way to the frontier {@link TeamPlan} gives it), how
 * many cells to drive straight, and how it keeps out of its teammates' way: it waits for a cell a
 * teammate holds (and after a while tries another way out), and steps aside for a teammate that
 * waits for its cell. {@link SearchPhases} asks; the answers are sides of the cell, 0 to 3, or -1
 * for none.
 */
final class Wayfinder {
    /** Steps a robot waits for a cell before it tries another way out. */
    private static final int PATIENCE = 60;
    /** The most cells a robot drives in one move. */
    static final int LONGEST_RUN = 8;

    private final ArRobot robot;
    private final int rank;
    private final MazeKnowledge map;
    private final Course course;
    private final HeatGuide heat;
    private final TeamTalk team;
    private final SplittableRandom random;

    /**
     * @param robot  the robot
     * @param rank   its number: lower numbers go first where robots meet
     * @param map    what it knows
     * @param course where it is and goes; the plan and the wait are set here
     * @param heat   its heat sensor's hints
     * @param team   its team messages, told when it starts waiting
     * @param random the robot's seeded tie-breaks
     */
    Wayfinder(ArRobot robot, int rank, MazeKnowledge map, Course course, HeatGuide heat, TeamTalk team,
              SplittableRandom random) {
        this.robot = robot;
        this.rank = rank;
        this.map = map;
        this.course = course;
        this.heat = heat;
        this.team = team;
        this.random = random;
    }

    /** @return the four sides, starting at a seeded one, so teammates fan out differently */
    int[] order() {
        int first = random.nextInt(4);
        return new int[] {first, (first + 1) % 4, (first + 2) % 4, (first + 3) % 4};
    }

    /**
     * Plans (the frontier to claim or follow, or the gold's cell when the heat places it in a cell
     * known to be reachable) and picks the side to leave by: towards the heat, else the first step
     * towards the target. A robot that follows a teammate's claim does not enter the frontier itself.
     *
     * @param order the side order, for ways of equal length
     * @return the side, or -1 for none
     */
    int chooseSide(int[] order) {
        int x = course.x();
        int y = course.y();
        TeamPlan.Plan plan = TeamPlan.plan(map, rank, x, y, order, robot.getStep());
        long goldCell = heat.goldCell();
        if (goldCell >= 0 && goldCell != course.here() && map.reach(x, y, order, Set.of()).containsKey(goldCell)) {
            plan = new TeamPlan.Plan(goldCell, true); // the heat places the gold in a cell known to be reachable
        }
        course.plan(plan);
        int d = goldCell >= 0 && plan.target() == goldCell ? -1 : heat.sideTowardsHeat();
        if (d < 0 && plan.target() >= 0) {
            d = TeamPlan.firstStep(map, x, y, plan.target(), order);
            if (d >= 0 && !plan.claim()
                    && MazeKnowledge.key(x + Directions.dx(d), y + Directions.dy(d)) == plan.target()) {
                d = -1; // following: the frontier itself is the claimant's to enter
            }
        }
        return d;
    }

    /**
     * How many cells to drive straight across {@code side} in one move, without stopping: on along
     * the way to the target while it keeps that direction through cells already sensed that no
     * teammate holds, up to {@value #LONGEST_RUN}; a cell nobody has sensed ends the run (it must be
     * sensed from its centre).
     */
    int runLength(int side, int[] order) {
        long target = course.plan().target();
        if (target < 0 || heat.sideTowardsHeat() >= 0) {
            return 1;
        }
        int x = course.x();
        int y = course.y();
        List<Long> path = map.path(x, y, MazeKnowledge.keyX(target), MazeKnowledge.keyY(target), order, map.held());
        int cells = 1;
        while (cells < path.size() && cells < LONGEST_RUN) {
            long here = path.get(cells - 1);
            long next = path.get(cells);
            if (!map.isSensed(MazeKnowledge.keyX(here), MazeKnowledge.keyY(here))
                    || MazeKnowledge.keyX(next) - MazeKnowledge.keyX(here) != Directions.dx(side)
                    || MazeKnowledge.keyY(next) - MazeKnowledge.keyY(here) != Directions.dy(side)
                    || (!course.plan().claim() && next == target)) {
                break;
            }
            cells++;
        }
        return path.isEmpty() || path.get(0) != MazeKnowledge.key(x + Directions.dx(side), y + Directions.dy(side))
                ? 1 : cells;
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
        Map<Long, MazeKnowledge.Reach> reach = map.reach(course.x(), course.y(), order(), held);
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

    /** @return whether a teammate stands in or drives into the cell across {@code side} */
    boolean heldByTeammate(int side) {
        return map.holder(course.x() + Directions.dx(side), course.y() + Directions.dy(side)) != null;
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
            team.tell(NONE, NONE, false);
        }
        course.waitOneStep();
        if (course.waited() >= PATIENCE * (1 + rank % 3)) {
            // stuck: any free open side other than the one wanted, then think again
            for (int s : order()) {
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

    /** @return whether a teammate stands in a cell of the run, or drives into one and goes before this robot */
    boolean runContested() {
        boolean contested = false;
        for (int k = 1; k <= course.cells(); k++) {
            contested |= contested(course.aheadX(k), course.aheadY(k));
        }
        return contested;
    }

    private boolean contested(int x, int y) {
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if ((m.x() == x && m.y() == y) || (m.nextX() == x && m.nextY() == y && Gold.rankOf(name) < rank)) {
                return true;
            }
        }
        return false;
    }
}
