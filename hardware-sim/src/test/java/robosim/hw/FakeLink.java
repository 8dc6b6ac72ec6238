package robosim.hw;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotState;
import robosim.protocol.RobotStates;
import robosim.protocol.Welcome;

/**
 * A link to an Environment played by the test, with no connection at all: the test delivers each
 * step itself ({@link #step}, on its own thread, as a link's reader would) and sees what the
 * hardware sends, with the thread that sent it.
 */
final class FakeLink implements EnvironmentLink {
    static final long WAIT_MS = 5_000;

    /** One step's requests as the hardware sent them. */
    record Sent(long step, List<RobotRequest> requests, String thread) {
    }

    private final IOException refusal;
    final BlockingQueue<Sent> sent = new LinkedBlockingQueue<>();
    final BlockingQueue<String> byes = new LinkedBlockingQueue<>();
    volatile RobotHello hello;
    volatile StepReceiver receiver;
    volatile boolean closed;

    /** A link whose Environment welcomes the robot. */
    FakeLink() {
        this(null);
    }

    /** @param refusal what opening throws, or null to welcome the robot */
    FakeLink(IOException refusal) {
        this.refusal = refusal;
    }

    static RobotState state(long step) {
        return RobotStates.of(step, step * 100, step * 10, 0, 0, 0, 0, 0, 0, false, new int[] {(int) (1000 + step)}, 0);
    }

    @Override
    public Welcome open(RobotHello hello, StepReceiver receiver) throws IOException {
        this.hello = hello;
        if (refusal != null) {
            throw refusal;
        }
        this.receiver = receiver;
        return new Welcome(hello.name(), 100, state(0));
    }

    /** Opens step {@code step}, delivering the state after the step before, on the calling thread. */
    void step(long step) {
        receiver.step(new RobotSensorResponse(step, state(step - 1)));
    }

    /** @return the next step's requests the hardware sent, waiting (bounded) for them */
    Sent next() throws InterruptedException {
        Sent s = sent.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        if (s == null) {
            throw new AssertionError("nothing was sent within " + WAIT_MS + " ms");
        }
        return s;
    }

    @Override
    public void send(long step, List<RobotRequest> requests) {
        sent.add(new Sent(step, List.copyOf(requests), Thread.currentThread().getName()));
    }

    @Override
    public void bye(String reason) {
        byes.add(reason);
        close();
    }

    @Override
    public void close() {
        closed = true;
    }

    @Override
    public String environment() {
        return "fake:1";
    }
}
