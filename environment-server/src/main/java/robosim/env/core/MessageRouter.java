package robosim.env.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import robosim.comms.CommsSettings;
import robosim.comms.CommunicationsSystem;
import robosim.comms.Positions;
import robosim.protocol.Command;
import robosim.protocol.MessageDelivery;

/**
 * The simulation's side of the CommunicationsSystem: turns robots' messaging requests into
 * submissions, and each step's deliveries and errors into what each robot reads next.
 */
final class MessageRouter {
    private final CommunicationsSystem comms;
    private final Map<String, List<MessageDelivery>> delivered = new HashMap<>();
    private final Map<String, List<String>> errors = new HashMap<>();
    private final Map<String, List<String>> pendingErrors = new HashMap<>();
    private final List<MessageDelivery> sent = new ArrayList<>();
    private final List<MessageDelivery> sentLastStep = new ArrayList<>();
    /** Each robot's count of messages accepted from it and delivered to it, for control clients' status. */
    private final Map<String, long[]> tallies = new HashMap<>();

    MessageRouter(List<String> robots, CommsSettings settings, long seed) {
        this.comms = new CommunicationsSystem(robots, settings, seed);
    }

    /** Adds a robot that joined the world during the run. */
    void addRobot(String robot) {
        comms.addRobot(robot);
    }

    /** Submits a message, or changes the robot's groups, as the command says. */
    void take(long step, String robot, Command.Messaging c) {
        if (c instanceof Command.SendMessage m) {
            String problem = comms.submit(step, robot, m);
            if (problem != null) {
                error(robot, problem);
            } else {
                String to = m.mode() == Command.Addressing.ALL ? "*" : m.to();
                sent.add(new MessageDelivery(robot, m.mode(), to, m.kind(), m.body(), step, m.id()));
            }
        } else if (c instanceof Command.JoinGroup j) {
            comms.join(robot, j.group());
        } else if (c instanceof Command.LeaveGroup l) {
            comms.leave(robot, l.group());
        } else {
            throw new IllegalStateException("the message router has no rule for " + c);
        }
    }

    /** Records an error for a robot, reported with the state after this step. */
    void error(String robot, String problem) {
        pendingErrors.computeIfAbsent(robot, k -> new ArrayList<>()).add(problem);
    }

    /** Delivers what is due after {@code step}; what each robot reads next replaces what it read. */
    void deliver(long step, Positions positions, Set<String> connected) {
        delivered.clear();
        delivered.putAll(comms.deliver(step, positions, connected));
        errors.clear();
        errors.putAll(pendingErrors);
        pendingErrors.clear();
        for (MessageDelivery m : sent) {
            tallies.computeIfAbsent(m.from(), k -> new long[2])[0]++;
        }
        delivered.forEach((robot, list) -> tallies.computeIfAbsent(robot, k -> new long[2])[1] += list.size());
        sentLastStep.clear();
        sentLastStep.addAll(sent);
        sent.clear();
    }

    /** @return the messages accepted in the last step, in the order they were sent */
    List<MessageDelivery> sentLastStep() {
        return List.copyOf(sentLastStep);
    }

    /** @return the robot's messages accepted and delivered since the run started, in that order */
    long[] tally(String robot) {
        return tallies.getOrDefault(robot, new long[2]).clone();
    }

    /** @return the copies of the robot's messages dropped on the way to a recipient, since the run started */
    long lost(String robot) {
        return comms.lost(robot);
    }

    List<MessageDelivery> delivered(String robot) {
        return delivered.getOrDefault(robot, List.of());
    }

    List<String> errors(String robot) {
        return errors.getOrDefault(robot, List.of());
    }

    CommsSettings settings() {
        return comms.settings();
    }

    void setSettings(CommsSettings settings) {
        comms.setSettings(settings);
    }
}
