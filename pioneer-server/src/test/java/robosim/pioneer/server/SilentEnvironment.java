package robosim.pioneer.server;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import robosim.params.ConversionFactors;
import robosim.protocol.RobotParameters;

/**
 * An "Environment" that takes robots' connections, reads their hello and says nothing, so that a
 * Pioneer port's robot waits for its welcome for as long as a test lasts.
 */
final class SilentEnvironment implements Closeable {
    private final List<Socket> held = new CopyOnWriteArrayList<>();
    private final CountDownLatch hello = new CountDownLatch(1);
    private final ServerSocket server;

    SilentEnvironment() throws IOException {
        server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        Thread t = new Thread(() -> {
            try {
                while (true) {
                    Socket s = server.accept();
                    held.add(s);
                    InputStream in = s.getInputStream();
                    if (in.read() >= 0) {
                        hello.countDown();
                    }
                }
            } catch (IOException closed) {
                // the test is over
            }
        }, "silent-environment");
        t.setDaemon(true);
        t.start();
    }

    /** @return the port robots connect to */
    int port() {
        return server.getLocalPort();
    }

    /** @return whether a robot said something within the time */
    boolean heardFrom(long timeout, TimeUnit unit) throws InterruptedException {
        return hello.await(timeout, unit);
    }

    /** @return a p3dx named r1 in a world of this step length */
    static ServedRobot robot(int stepMs) {
        return new ServedRobot("r1", "pioneer", new RobotParameters("Pioneer", "p3dx", 250, 425, 210, 301, 2200, 500,
                300, 300, 100, 100, 0.0056, 5000, List.of()), new ConversionFactors(0.001534, 0.485, 1, 1, 0.0056, 20),
                stepMs);
    }

    @Override
    public void close() throws IOException {
        server.close();
        for (Socket s : held) {
            s.close();
        }
    }
}
