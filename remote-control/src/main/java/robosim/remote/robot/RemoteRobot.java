package robosim.remote.robot;

import robosim.hw.AbstractRobot;
import robosim.hw.RobotMessage;
import robosim.hw.RunEnd;
import robosim.remote.DriveTarget;
import robosim.remote.Inbox;
import robosim.remote.MessageDraft;
import robosim.remote.Readings;
import robosim.protocol.RobotParameters;

/**
 * A connected robot driven by hand. The thread that calls {@link #run()} is the robot's program:
 * it yields each step (so the robot's requests, queued by the window's thread at any time, go out
 * with the next step), then takes the step's readings and messages. The window reads
 * {@link #latest()} and {@link #inbox()}, which are safe from any thread.
 */
public abstract class RemoteRobot implements DriveTarget {
    private final Inbox inbox = new Inbox();
    private volatile Readings latest;

    /** @return the robot underneath, for messages and leaving */
    protected abstract AbstractRobot robot();

    /** @return true after waiting, yielded, for the next step; false once the robot left the run */
    protected abstract boolean awaitStep();

    /** @return this step's readings; called on the robot's thread, right after {@link #awaitStep()} */
    protected abstract Readings read();

    /** Runs the robot's side until it leaves the run (the Environment ends it, or {@link #disconnect()}). */
    public final void run() {
        while (awaitStep()) {
            latest = read();
            for (RobotMessage m = robot().poll(); m != null; m = robot().poll()) {
                inbox.add(Inbox.line(m.sentStep(), m.from(), m.to(), m.kind(), m.text()));
            }
        }
    }

    /** @return the latest step's readings, or null before the first */
    public final Readings latest() {
        return latest;
    }

    /** @return the messages received */
    public final Inbox inbox() {
        return inbox;
    }

    /** Leaves the run; {@link #run()} then returns. */
    public final void disconnect() {
        robot().disconnect();
    }

    /** @return how the robot's part in the run ended, or null while it lasts */
    public final RunEnd runEnd() {
        return robot().getRunEnd();
    }

    @Override
    public final String name() {
        return robot().getName();
    }

    @Override
    public final RobotParameters parameters() {
        return robot().getParameters();
    }

    @Override
    public final void send(MessageDraft message) {
        switch (message.to()) {
            case ALL -> robot().broadcast(message.text());
            case ROBOT -> robot().send(message.name(), message.text());
            case GROUP -> robot().multicast(message.name(), message.text());
            default -> throw new IllegalStateException("no such recipient: " + message.to());
        }
    }
}
