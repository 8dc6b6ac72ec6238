package robosim.env.net;

import robosim.env.core.Find;
import robosim.env.core.Simulation;
import robosim.env.world.EndRule;
import robosim.protocol.Snapshot;

/**
 * When a run ends of itself: a robot's request to end it, the world's {@link EndRule}, and
 * {@code env --steps} whatever the rule. Checked by the step loop between steps.
 */
final class EndConditions {
    private EndConditions() {
    }

    /**
     * A robot's request comes first: it asked in the step just run, for a reason of its own, which
     * the report should give even when a limit falls on the same step.
     *
     * @param sim        the run
     * @param rules      the session rules, for the robots connected and gone
     * @param stepLimit  {@code env --steps}, 0 for none
     * @return how and why the run ends now, or null
     */
    static EndOfRun ending(Simulation sim, SessionRules rules, long stepLimit) {
        Snapshot.EndRequest asked = sim.endRequest();
        if (asked != null) {
            return new EndOfRun(RunEnding.ROBOT_ENDED, "ended by robot " + asked.robot() + " at step " + asked.step()
                    + ": " + asked.reason());
        }
        EndRule end = sim.world().rules().end();
        if (end.whenAllGone() && rules.connectedRobots().isEmpty()) {
            return new EndOfRun(RunEnding.ALL_GONE, "every robot has disconnected");
        }
        if (end.when() == EndRule.When.ANY_LEFT && !rules.departures().isEmpty()) {
            Departure d = rules.departures().get(0);
            return new EndOfRun(RunEnding.ROBOT_LEFT, "robot " + d.robot() + " " + d.describe()
                    + " (the world ends the run when any robot leaves)");
        }
        long k = sim.stepCount();
        if (stepLimit > 0 && k >= stepLimit) {
            return new EndOfRun(RunEnding.STEP_LIMIT, "step limit " + stepLimit + " reached");
        }
        if (end.steps() > 0 && k >= end.steps()) {
            return new EndOfRun(RunEnding.WORLD_STEP_LIMIT, "the world's step limit " + end.steps() + " reached");
        }
        // a find ends the run once the finder's news has had time to reach its team
        Find find = sim.find();
        if (end.whenGoldFound() && find != null && k >= find.step() + sim.commsSettings().latencySteps() + 1) {
            return new EndOfRun(RunEnding.GOLD_FOUND, "gold found by " + find.robot() + " at step " + find.step());
        }
        return null;
    }
}
