package robosim.env.net;

import robosim.env.core.Find;
import robosim.env.core.Simulation;
import robosim.env.world.EndRule;

/**
 * When a run ends of itself: the world's {@link EndRule}, and {@code env --steps} whatever the rule.
 * Checked by the step loop between steps.
 */
final class EndConditions {
    private EndConditions() {
    }

    /**
     * @param sim        the run
     * @param rules      the session rules, for the robots connected and gone
     * @param stepLimit  {@code env --steps}, 0 for none
     * @return why the run ends now, or null
     */
    static String reason(Simulation sim, SessionRules rules, long stepLimit) {
        EndRule end = sim.world().rules().end();
        if (end.whenAllGone() && rules.connectedRobots().isEmpty()) {
            return "every robot has disconnected";
        }
        if (end.when() == EndRule.When.ANY_LEFT && !rules.departures().isEmpty()) {
            Departure d = rules.departures().get(0);
            return "robot " + d.robot() + " " + d.describe() + " (the world ends the run when any robot leaves)";
        }
        long k = sim.stepCount();
        if (stepLimit > 0 && k >= stepLimit) {
            return "step limit " + stepLimit + " reached";
        }
        if (end.steps() > 0 && k >= end.steps()) {
            return "the world's step limit " + end.steps() + " reached";
        }
        // a find ends the run once the finder's news has had time to reach its team
        Find find = sim.find();
        if (end.whenGoldFound() && find != null && k >= find.step() + sim.commsSettings().latencySteps() + 1) {
            return "gold found by " + find.robot() + " at step " + find.step();
        }
        return null;
    }
}
