package robosim.it;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import robosim.params.ParameterFileReader;
import robosim.protocol.Bye;
import robosim.protocol.CommsUpdate;
import robosim.protocol.Fuzz;
import robosim.protocol.LinkHello;
import robosim.protocol.LinkRequests;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.PayloadMutator;
import robosim.protocol.RandomMessages;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotRequests;
import robosim.protocol.ViewerHello;

/**
 * Peers that break the protocol in every way a seeded random source picks, on raw sockets to an
 * Environment's robot and viewer ports: garbage bytes, frames of garbage, lengths no writer would
 * put, hellos damaged byte by byte or field by field, hellos for robots already connected or
 * unknown, shared links sending requests for robots they do not carry, requests before any
 * hello, any message where it does not belong, frames cut short and left hanging. They never read:
 * what the Environment sends them piles up until it closes them. {@link #close()} closes them all.
 */
final class HostilePeers implements AutoCloseable {
    private static final MessageCodec CODEC = new MessageCodec();

    private final Fuzz fuzz;
    private final Random random;
    private final int robotPort;
    private final int viewerPort;
    private final List<String> names;
    private final RobotParameters params;
    private final List<Socket> open = new ArrayList<>();

    /**
     * @param fuzz       the case, for its random source and its mutations
     * @param robotPort  the Environment's robot port
     * @param viewerPort its viewer port
     * @param names      names to claim: the world's robots, and others
     */
    HostilePeers(Fuzz fuzz, int robotPort, int viewerPort, List<String> names) {
        this.fuzz = fuzz;
        this.random = fuzz.random();
        this.robotPort = robotPort;
        this.viewerPort = viewerPort;
        this.names = names;
        this.params = ParameterFileReader.read(LocalEnvironment.root().resolve("testLoadFiles/robots/p3dx.p"));
    }

    /** Opens {@code peers} connections, each sending what one hostile peer sends during step {@code step}. */
    void attack(long step, int peers) {
        for (int i = 0; i < peers; i++) {
            boolean robot = random.nextInt(3) > 0;
            byte[] bytes = robot ? robotPeer(step) : viewerPeer();
            try {
                Socket s = new Socket("127.0.0.1", robot ? robotPort : viewerPort);
                open.add(s);
                OutputStream out = s.getOutputStream();
                // in one write or in pieces, as TCP may deliver it
                for (int at = 0; at < bytes.length; ) {
                    int n = random.nextBoolean() ? bytes.length - at : 1 + random.nextInt(bytes.length - at);
                    out.write(bytes, at, n);
                    out.flush();
                    at += n;
                }
                if (random.nextBoolean()) {
                    s.close();
                }
            } catch (IOException e) {
                // the Environment may close a hostile peer before it has written everything: that is its right
            }
        }
    }

    /** @return what one hostile robot connection sends, as the bytes of one or more frames */
    private byte[] robotPeer(long step) {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        switch (random.nextInt(9)) {
            case 0 -> b.writeBytes(fuzz.garbage(1 + random.nextInt(200)));
            case 1 -> b.writeBytes(frame(fuzz.garbage(1 + random.nextInt(200))));
            case 2 -> {
                b.writeBytes(ByteBuffer.allocate(4).putInt(Fuzz.EDGE_INTS[random.nextInt(Fuzz.EDGE_INTS.length)]).array());
                b.writeBytes(fuzz.garbage(random.nextInt(64)));
            }
            case 3 -> b.writeBytes(frame(fuzz.mutate(CODEC.encode(hello()))));
            case 4 -> b.writeBytes(frame(new PayloadMutator(random).mutate(hello(), true)));
            case 5 -> {
                b.writeBytes(frame(hello()));
                b.writeBytes(frame(new RobotRequests(step + random.nextInt(3) - 1, new RandomMessages(random).commands())));
            }
            case 6 -> {
                b.writeBytes(frame(new LinkHello(text())));
                b.writeBytes(frame(hello()));
                b.writeBytes(frame(new LinkRequests(step + random.nextInt(3) - 1, List.of(new LinkRequests.ForRobot(
                        name(), new RandomMessages(random).commands())))));
                b.writeBytes(frame(new Bye(text(), name())));
                b.writeBytes(frame(fuzz.mutate(CODEC.encode(new RandomMessages(random).any()))));
            }
            case 7 -> b.writeBytes(frame(new RandomMessages(random).any()));
            default -> {
                byte[] f = frame(new RobotRequests(step, new RandomMessages(random).commands()));
                b.write(f, 0, random.nextInt(f.length));
            }
        }
        return b.toByteArray();
    }

    /** @return what one hostile viewer connection sends */
    private byte[] viewerPeer() {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        RandomMessages messages = new RandomMessages(random);
        switch (random.nextInt(5)) {
            case 0 -> b.writeBytes(fuzz.garbage(1 + random.nextInt(200)));
            case 1 -> b.writeBytes(frame(new PayloadMutator(random).mutate(new ViewerHello(text()), true)));
            case 2 -> {
                b.writeBytes(frame(new ViewerHello(text())));
                b.writeBytes(frame(random.nextBoolean() ? new ViewerHello("again") : messages.any()));
            }
            case 3 -> {
                b.writeBytes(frame(new ViewerHello(null)));
                b.writeBytes(frame(new PayloadMutator(random).mutate(new CommsUpdate(null, null, null, null, null), true)));
            }
            default -> {
                b.writeBytes(frame(new ViewerHello(text())));
                b.writeBytes(frame(fuzz.mutate(CODEC.encode(messages.any()))));
            }
        }
        return b.toByteArray();
    }

    /** @return a hello for one of the names, now and then of the wrong type or with parameters out of bounds */
    private RobotHello hello() {
        String type = random.nextInt(4) == 0 ? text() : "pioneer";
        return new RobotHello(name(), type, random.nextInt(4) == 0 ? new RobotParameters(params.robotClass(),
                params.subclass(), 1e12, -1, Double.NaN, 0, 1e9, 0, 0, 0, 0, 0, 0, 0, params.sonarUnits()) : params);
    }

    /** @return text a peer may choose for itself: printable, or with line breaks and other control characters */
    private String text() {
        return random.nextBoolean() ? "hostile\nSEVERE: forged" : new RandomMessages(random).text(40);
    }

    private String name() {
        return names.get(random.nextInt(names.size()));
    }

    private byte[] frame(Message m) {
        return frame(CODEC.encode(m));
    }

    private static byte[] frame(byte[] payload) {
        return ByteBuffer.allocate(4 + payload.length).putInt(payload.length).put(payload).array();
    }

    @Override
    public void close() {
        for (Socket s : open) {
            try {
                s.close();
            } catch (IOException e) {
                // closing is all that is left to do
            }
        }
    }
}
