package robosim.it;

import java.util.List;
import java.util.concurrent.Callable;
import robosim.protocol.Bye;
import robosim.protocol.Message;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotRequests;
import robosim.protocol.TimeStep;

/**
 * A robot program on a raw socket that stands still, and after a number of steps says bye and
 * goes (or stays to the end). Returns what became of it: its own bye, or the Environment's reason.
 */
final class Visitor implements Callable<String> {
    private final int port;
    private final String name;
    private final RobotParameters params;
    private final int stepsBeforeLeaving;

    /**
     * @param stepsBeforeLeaving the steps it answers before it leaves, or 0 to stay to the end
     */
    Visitor(int port, String name, RobotParameters params, int stepsBeforeLeaving) {
        this.port = port;
        this.name = name;
        this.params = params;
        this.stepsBeforeLeaving = stepsBeforeLeaving;
    }

    @Override
    public String call() throws Exception {
        try (RawPeer peer = new RawPeer(port)) {
            peer.send(new RobotHello(name, "pioneer", params));
            int answered = 0;
            Message m;
            while ((m = peer.read()) != null) {
                if (m instanceof TimeStep t) {
                    if (stepsBeforeLeaving > 0 && answered == stepsBeforeLeaving) {
                        peer.send(new Bye("done visiting"));
                        return "left";
                    }
                    peer.send(new RobotRequests(t.step(), List.of()));
                    answered++;
                } else if (m instanceof Bye bye) {
                    return bye.reason();
                }
            }
            return "closed without a bye";
        }
    }
}
