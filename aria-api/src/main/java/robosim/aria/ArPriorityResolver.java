package robosim.aria;

import java.util.List;

/**
 * ARIA's default resolver (ArPriorityResolver.cpp): the actions of one priority are averaged
 * channel by channel, weighted by strength (their strengths add up, capped at 1); each priority's
 * average is then merged into the desire of the higher priorities, getting only the strength they
 * left below 1. So a higher priority at full strength decides a channel alone, and lower ones fill
 * in what it leaves. Each action is fired with the desire of the priorities above it (a copy); a set
 * absolute heading is turned into a delta from the robot's heading and the desire is sanity-checked
 * before it is added.
 *
 * <p>One of ARIA's rules surprises: within one priority, a channel combined by the safer value (a
 * maximum velocity, say) takes the value of the action fired last, not the safest of them, because
 * ARIA's averaging leaves the channel's strength at 0 until the priority ends. Across priorities the
 * safer value wins. RoboSim keeps ARIA's rule, so that programs behave as under ARIA; give limiters
 * priorities of their own when several must all hold.
 */
public class ArPriorityResolver extends ArResolver {
    private final ArActionDesired result = new ArActionDesired();

    /** A priority resolver. */
    public ArPriorityResolver() {
        super("ArPriorityResolver", "Resolves by priority: the strength a higher priority leaves goes to the lower ones;"
                + " actions of one priority are averaged by strength.");
    }

    @Override
    public ArActionDesired resolve(List<Entry> actions, ArRobot robot, boolean logActions) {
        if (actions == null) {
            return null;
        }
        result.reset();
        ArActionDesired averaging = new ArActionDesired();
        averaging.startAverage();
        boolean first = true;
        int lastPriority = 0;
        for (Entry e : actions) {
            ArAction action = e.action();
            if (action == null || !action.isActive()) {
                continue;
            }
            if (first || e.priority() != lastPriority) {
                averaging.endAverage();
                result.merge(averaging);
                averaging.reset();
                averaging.startAverage();
                first = false;
                lastPriority = e.priority();
            }
            ArActionDesired act = action.fire(result.copy());
            if (act != null) {
                if (robot != null) {
                    act.accountForRobotHeading(robot.getTh());
                }
                act.sanityCheck(action.getName());
                averaging.addAverage(act);
                if (logActions && act.isAnythingDesired()) {
                    ArLogs.info("priority " + e.priority() + ", " + action.getName() + ": " + act);
                }
            }
        }
        averaging.endAverage();
        result.merge(averaging);
        return result;
    }
}
