package robosim.hw;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import robosim.pioneer.Commands;
import robosim.pioneer.ConfigPacket;
import robosim.pioneer.PacketDecoder;
import robosim.pioneer.PioneerPacket;
import robosim.pioneer.RobotIdentity;
import robosim.pioneer.Sip;

/**
 * A Pioneer robot server played by a test, on loopback: it answers the handshake and CONFIG as
 * MobileSim does (subclass {@code p3dx-sh}, a SIP cycle of 50 ms), sends a given number of SIPs
 * after CONFIG (its motors disabled, as a Pioneer's are when a client opens it) and then falls silent, and keeps every command it receives. One client; closed by
 * {@link #close()}.
 */
final class FakePioneerServer implements AutoCloseable {
    private final ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    private final int sips;
    final BlockingQueue<PioneerPacket> received = new LinkedBlockingQueue<>();
    private final Thread thread;
    private volatile Socket socket;

    /** @param sips the SIPs it sends after CONFIG before it falls silent */
    FakePioneerServer(int sips) throws IOException {
        this.sips = sips;
        thread = new Thread(this::serve, "fake-pioneer");
        thread.setDaemon(true);
        thread.start();
    }

    int port() {
        return server.getLocalPort();
    }

    private void serve() {
        try (Socket s = server.accept(); InputStream in = s.getInputStream(); OutputStream out = s.getOutputStream()) {
            socket = s;
            boolean[] synced = {false};
            PacketDecoder decoder = new PacketDecoder(new PacketDecoder.Listener() {
                @Override
                public void packet(PioneerPacket p) {
                    try {
                        answer(p, out, synced);
                    } catch (IOException | InterruptedException e) {
                        throw new IllegalStateException(e);
                    }
                }

                @Override
                public void dropped(String reason) {
                    throw new IllegalStateException("the link sent a bad packet: " + reason);
                }
            });
            byte[] buf = new byte[512];
            int n;
            while ((n = in.read(buf)) > 0) {
                decoder.feed(buf, 0, n);
            }
        } catch (IOException | IllegalStateException e) {
            // the test closed it, or the link left
        }
    }

    private void answer(PioneerPacket p, OutputStream out, boolean[] synced) throws IOException, InterruptedException {
        if (!synced[0]) {
            out.write(p.id() == Commands.SYNC2 ? new RobotIdentity("MobileSim", "Pioneer", "p3dx-sh").toPacket().encode()
                    : p.encode());
            synced[0] = p.id() == Commands.SYNC2;
            return;
        }
        received.add(p);
        if (p.id() == Commands.CONFIG) {
            out.write(new ConfigPacket("Pioneer", "p3dx-sh", "SIM", 500, 2200, 300, 300, "fake", 50, false, true, true,
                    2000, 500, 2200, 100, 100, 300, 300, 0, 0, "S.0").toPacket().encode());
            for (int i = 0; i < sips; i++) {
                out.write(new Sip(false, 10 * i, 0, 0, 0, 0, 130, 0, 0, Sip.FLAG_SONARS, 0,
                        List.of(new Sip.SonarReading(3, 700)), 0xff, 0xff, 130, 0, 0, 0, 0, -127, 0).toPacket().encode());
                Thread.sleep(50); // MobileSim's SIP cycle: a peer's pace, what the link under test must follow
            }
        }
    }

    @Override
    public void close() throws Exception {
        server.close();
        Socket s = socket;
        if (s != null) {
            s.close();
        }
        thread.join(5_000);
    }
}
