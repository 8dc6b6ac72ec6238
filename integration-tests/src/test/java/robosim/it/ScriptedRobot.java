package robosim.it;

import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import robosim.protocol.Bye;
import robosim.protocol.Command;
import robosim.protocol.KeepAlive;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotRequests;
import robosim.protocol.TimeStep;

/**
 * A robot program on a raw socket whose requests depend on the step number alone, so that two runs
 * with the same seed give the same trajectory however long the Environment pauses between steps.
 * Counts the keep-alives it hears; returns the reason of the Environment's bye.
 */
final class ScriptedRobot implements Callable<String> {
    final AtomicInteger keepAlives = new AtomicInteger();
    private final int port;
    private final String name;
    private final RobotParameters params;
    private final boolean moving;

    /**
     * @param moving whether it drives (a curve that turns every 20 steps), or stays where it stands
     */
    ScriptedRobot(int port, String name, RobotParameters params, boolean moving) {
        this.port = port;
        this.name = name;
        this.params = params;
        this.moving = moving;
    }

    /** @return the requests for a step: a new speed and turn every 20 steps */
    private List<Command> commands(long step) {
        if (!moving || step % 20 != 1) {
            return List.of();
        }
        // a robot program enables a Pioneer's motors before it drives, as an ARIA program does
        return List.of(new Command.SetMotors(true), new Command.SetVel(300),
                new Command.SetRotVel(step % 40 < 20 ? 15 : -10));
    }

    @Override
    public String call() throws Exception {
        try (RawPeer peer = new RawPeer(port)) {
            peer.send(new RobotHello(name, "pioneer", params));
            Message m;
            while ((m = peer.read()) != null) {
                if (m instanceof TimeStep t) {
                    peer.send(new RobotRequests(t.step(), commands(t.step())));
                } else if (m instanceof KeepAlive) {
                    keepAlives.incrementAndGet();
                } else if (m instanceof Bye bye) {
                    return bye.reason();
                }
            }
            return "closed without a bye";
        }
    }
}
