package robosim.it;

import java.io.IOException;
import java.util.List;
import robosim.protocol.Bye;
import robosim.protocol.ControlHello;
import robosim.protocol.ControlReply;
import robosim.protocol.ControlRequest;
import robosim.protocol.Message;

/** A control client on a raw socket: says hello, then asks and reads the answers, each wait bounded. */
final class ControlPeer implements AutoCloseable {
    final RawPeer peer;
    private long next = 1;

    ControlPeer(int viewerPort, String name) throws IOException {
        peer = new RawPeer(viewerPort);
        peer.send(new ControlHello(name, null));
    }

    /** Sends a request without waiting for its answer. */
    void send(String op, String... args) throws IOException {
        peer.send(new ControlRequest(next++, op, List.of(args)));
    }

    /** @return the next answer; fails on anything else but a keep-alive-free stream of answers */
    ControlReply reply() throws IOException {
        Message m = peer.read();
        if (m instanceof ControlReply r) {
            return r;
        }
        throw new AssertionError("expected a controlReply, got " + (m instanceof Bye b ? "bye: " + b.reason() : m));
    }

    /** Sends a request and reads its answer, passing over the answers to requests sent before it without waiting. */
    ControlReply ask(String op, String... args) throws IOException {
        send(op, args);
        ControlReply r = reply();
        while (r.id() < next - 1) {
            r = reply();
        }
        if (r.id() != next - 1) {
            throw new AssertionError("the answer " + r + " is not to request " + (next - 1));
        }
        return r;
    }

    @Override
    public void close() throws IOException {
        peer.close();
    }
}
