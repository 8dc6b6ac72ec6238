package robosim.env.net;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import robosim.env.core.RobotSummary;
import robosim.env.core.Simulation;
import robosim.protocol.ControlReply;
import robosim.protocol.ControlRequest;
import robosim.protocol.Message;
import robosim.protocol.RunStatus;
import robosim.protocol.Snapshot;

/**
 * The answer to a control client's {@code status} request: the run and every robot as a
 * ControlPanel's table shows them ({@link RunStatus}). Read-only: it changes nothing in the run.
 */
final class StatusReport {
    /** The operation's name on the wire. */
    static final String OP = "status";

    private StatusReport() {
    }

    /**
     * @param r      the request
     * @param sim    the run's simulation
     * @param rules  the sessions, for who drives each robot and the steps they answered
     * @param paused whether the run is paused
     * @param pace   the pace in force: 0 for as fast as possible
     * @return the status, or a refusal when the request carries arguments
     */
    static Message answer(ControlRequest r, Simulation sim, RunSessions rules, boolean paused, double pace) {
        if (!r.args().isEmpty()) {
            return new ControlReply(r.id(), false, "status takes 0 arguments (status), got " + r.args().size());
        }
        Map<String, Connection> connected = rules.connectedRobots();
        List<RunStatus.RobotStatus> rows = new ArrayList<>();
        for (Snapshot.RobotView v : sim.snapshot().robots()) {
            RobotSummary s = sim.summary(v.name());
            long[] counts = sim.messageCounts(v.name());
            Connection c = connected.get(v.name());
            // the body's type: a world's robot's as declared, a newcomer's in an open world as it said
            String type = sim.type(v.name());
            rows.add(new RunStatus.RobotStatus(v.name(), type, c == null ? "" : drivenBy(c), c != null, v.x(), v.y(),
                    v.th(), v.vel(), v.rotVel(), v.stalled(), s.collisions(), counts[0], counts[1],
                    rules.lastAnswered(v.name())));
        }
        return new RunStatus(r.id(), sim.world().name(), sim.stepCount(), sim.timeMs(), paused, pace, rows);
    }

    /** @return what drives a robot, as a user reads it: its own program, or a link carrying many */
    private static String drivenBy(Connection c) {
        return (c.isLink() ? "link at " : "program at ") + c.address().replaceFirst("^/", "");
    }
}
