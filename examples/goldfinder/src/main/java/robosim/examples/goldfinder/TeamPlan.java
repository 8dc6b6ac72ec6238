package robosim.examples.goldfinder;

import java.util.Map;
import java.util.Set;

/**
 * How a Gold robot divides the search with its team, from what it knows alone (no negotiation, so
 * lost or late messages cost time, never the search): every robot claims one frontier, the
 * nearest one that no teammate nearer to it has claimed, and tells the team. A claim lasts while
 * its robot keeps repeating it: one not heard again for {@link #CLAIM_STEPS} steps (the message was
 * lost, the robot is gone) is free for the others to take.
 *
 * <p>Two robots that claim the same frontier settle it the same way on both sides: the one that
 * would get there first keeps it, and between equal ways the lower number. A robot's way there is
 * counted as it drives it: through the cells ahead it has committed to, then on from the last of
 * them (a robot plans from there, so counting a teammate's way from the cell it stands in would
 * favour the teammate wrongly when it has committed to drive away from the frontier).
 *
 * <p>A robot that finds no frontier left to claim follows a claimed one, to be at hand when the
 * branch forks: the one the fewest teammates already follow from nearer, then the nearest. A
 * second follower behind the first is of no use at the next fork while another claim has none.
 * It never enters a cell a teammate holds.
 */
final class TeamPlan {
    /** Steps a claim lasts without being heard again: ten heartbeats. */
    static final long CLAIM_STEPS = 150;
    /** The direction order in which every robot computes a teammate's path, so all agree. */
    private static final int[] FIXED = {0, 1, 2, 3};

    private TeamPlan() {
    }

    /**
     * What to do next.
     *
     * @param target the frontier claimed or followed (a cell key), or -1 for none
     * @param claim  whether the target is claimed (not only followed)
     */
    record Plan(long target, boolean claim) {
        static final Plan NONE = new Plan(-1, false);

        int x() {
            return MazeKnowledge.keyX(target);
        }

        int y() {
            return MazeKnowledge.keyY(target);
        }
    }

    /**
     * @param map   what the robot knows
     * @param rank  the robot's number (lower goes first)
     * @param x     its cell's column
     * @param y     its cell's row
     * @param order its direction order, for paths of equal length
     * @param now   the current step
     * @return the frontier to claim, or one to follow, or {@link Plan#NONE} when nothing is left
     */
    static Plan plan(MazeKnowledge map, int rank, int x, int y, int[] order, long now) {
        return plan(map, rank, x, y, 0, order, now);
    }

    /**
     * What to do next, planned from the last cell the robot has committed to.
     *
     * @param map       what the robot knows
     * @param rank      the robot's number (lower goes first)
     * @param x         the column of the last cell it has committed to
     * @param y         that cell's row
     * @param committed how many cells ahead it has committed to, the last of them (x, y): its way
     *                  to a frontier is that many cells longer than the way from there
     * @param order     its direction order, for paths of equal length
     * @param now       the current step
     * @return the frontier to claim, or one to follow, or {@link Plan#NONE} when nothing is left
     */
    static Plan plan(MazeKnowledge map, int rank, int x, int y, int committed, int[] order, long now) {
        Map<Long, MazeKnowledge.Reach> mine = map.reach(x, y, order, Set.of());
        long best = -1;
        int bestCells = Integer.MAX_VALUE;
        long follow = -1;
        int followCells = Integer.MAX_VALUE;
        int followAhead = Integer.MAX_VALUE;
        // in the order the cells were reached: between frontiers as near, the direction order decides
        for (Map.Entry<Long, MazeKnowledge.Reach> e : mine.entrySet()) {
            long f = e.getKey();
            MazeKnowledge.Reach r = e.getValue();
            if (r.cells() == 0 || map.isSensed(MazeKnowledge.keyX(f), MazeKnowledge.keyY(f))) {
                continue;
            }
            if (entered(map, f) || !wins(map, rank, committed + r.cells(), f, now)) {
                int ahead = followersAhead(map, rank, committed + r.cells(), f);
                if (ahead < followAhead || (ahead == followAhead && r.cells() < followCells)) {
                    follow = f;
                    followCells = r.cells();
                    followAhead = ahead;
                }
                continue;
            }
            if (r.cells() < bestCells) {
                best = f;
                bestCells = r.cells();
            }
        }
        if (best >= 0) {
            return new Plan(best, true);
        }
        return follow >= 0 ? new Plan(follow, false) : Plan.NONE;
    }

    /** Whether a teammate is driving into the frontier already: it will be sensed in a moment. */
    private static boolean entered(MazeKnowledge map, long f) {
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if (m.route().contains(f)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether this robot, {@code cells} from frontier {@code f} on the way it drives, may claim it:
     * no teammate with a live claim on it would get there sooner ({@link #cellsTo}), or as soon with
     * a lower number.
     */
    static boolean wins(MazeKnowledge map, int rank, int cells, long f, long now) {
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if (!m.claims() || MazeKnowledge.key(m.claimX(), m.claimY()) != f || now - m.heard() > CLAIM_STEPS) {
                continue;
            }
            int their = cellsTo(map, m, f);
            if (their < cells || (their == cells && Gold.rankOf(name) < rank)) {
                return false;
            }
        }
        return true;
    }

    /**
     * How many teammates follow frontier {@code f} (they told it as their target, unclaimed) and
     * would get there sooner than this robot, {@code cells} from it, or as soon with a lower number.
     */
    private static int followersAhead(MazeKnowledge map, int rank, int cells, long f) {
        int ahead = 0;
        for (String name : map.mates()) {
            MazeKnowledge.Mate m = map.mate(name);
            if (m.claims() || m.target() != f) {
                continue;
            }
            int their = cellsTo(map, m, f);
            if (their < cells || (their == cells && Gold.rankOf(name) < rank)) {
                ahead++;
            }
        }
        return ahead;
    }

    /**
     * A teammate's way to a cell, in cells, as it drives it: through the cells ahead it has
     * committed to, then on from the last of them by a shortest known path (every robot computes
     * it in one fixed direction order, so all agree); from the cell it stands in if that gives no
     * way (it drives into a frontier, which has no known way on yet).
     *
     * @return the cells, or {@link Integer#MAX_VALUE} if no way is known
     */
    static int cellsTo(MazeKnowledge map, MazeKnowledge.Mate m, long cell) {
        if (!m.route().isEmpty()) {
            long last = m.route().get(m.route().size() - 1);
            MazeKnowledge.Reach on = map.reach(MazeKnowledge.keyX(last), MazeKnowledge.keyY(last), FIXED, Set.of())
                    .get(cell);
            if (on != null) {
                return m.route().size() + on.cells();
            }
        }
        MazeKnowledge.Reach from = map.reach(m.x(), m.y(), FIXED, Set.of()).get(cell);
        return from == null ? Integer.MAX_VALUE : from.cells();
    }

    /**
     * The first step towards a target: along a shortest known path around the cells teammates
     * hold if there is one, else along a shortest path through them (to wait for them to move).
     *
     * @return the direction, or -1 if the target cannot be reached or is here
     */
    static int firstStep(MazeKnowledge map, int x, int y, long target, int[] order) {
        MazeKnowledge.Reach around = map.reach(x, y, order, map.held()).get(target);
        if (around != null && around.first() >= 0) {
            return around.first();
        }
        MazeKnowledge.Reach through = map.reach(x, y, order, Set.of()).get(target);
        return through == null ? -1 : through.first();
    }
}
