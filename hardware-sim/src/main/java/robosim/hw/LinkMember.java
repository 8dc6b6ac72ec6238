package robosim.hw;

import java.io.IOException;
import java.util.List;
import java.util.function.Supplier;
import robosim.protocol.Bye;
import robosim.protocol.RobotHello;
import robosim.protocol.Welcome;

/**
 * One robot's part of its runtime's {@link SharedLink} to an Environment: opening it joins the link
 * (connecting it if none is open), closing it leaves the link, which goes on for the others.
 */
final class LinkMember extends ReleasedOnClose {
    private final RobotRuntime runtime;
    private final String host;
    private final int port;
    private final HardwareOptions options;
    private volatile SharedLink link;
    private volatile String name;
    private volatile StepReceiver receiver;

    LinkMember(RobotRuntime runtime, String host, int port, HardwareOptions options, Runnable released) {
        super(released);
        this.runtime = runtime;
        this.host = host;
        this.port = port;
        this.options = options;
    }

    @Override
    public Welcome open(RobotHello hello, StepReceiver receiver) throws IOException {
        return open(hello, null, receiver);
    }

    @Override
    public Welcome open(RobotHello hello, Supplier<String> secret, StepReceiver receiver) throws IOException {
        this.name = hello.name();
        this.receiver = receiver;
        try {
            link = runtime.sharedLinks().to(host, port, options, secret != null ? secret : hello::token);
            return link.join(this, hello);
        } catch (IOException | RuntimeException e) {
            close();
            throw e;
        }
    }

    @Override
    public void send(long step, List<RobotRequest> requests) {
        link.submit(this, step, requests);
    }

    @Override
    public void bye(String reason) {
        SharedLink l = link;
        if (l != null && !isClosed()) {
            l.write(new Bye(reason, name));
        }
        close();
    }

    @Override
    void closed() {
        SharedLink l = link;
        if (l != null) {
            l.leave(this);
        }
    }

    /** @return the robot's name, once opened */
    String name() {
        return name;
    }

    /** @return where its steps go, once opened */
    StepReceiver receiver() {
        return receiver;
    }

    /** The link ended the robot's part, or the whole link ended. */
    void ended(RunEnd.Kind kind, String reason) {
        receiver.ended(kind, reason);
        close();
    }

    @Override
    public String environment() {
        return host + ":" + port;
    }
}
