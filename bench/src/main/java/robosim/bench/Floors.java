package robosim.bench;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.lang.reflect.Method;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;

/**
 * What one step of lockstep cannot go below on this machine, measured without RoboSim: handing
 * control from one thread to another and back (park/unpark ping-pong, platform threads, and
 * virtual threads where the JDK has them), and a loopback TCP round trip with TCP_NODELAY carrying
 * a time step's and a requests frame's sizes. The figures are per hand-off and per round trip.
 */
public final class Floors {
    /** Bytes of a one-robot time step frame, and of its requests frame. */
    private static final int STEP_BYTES = 248;
    private static final int REQUESTS_BYTES = 97;

    private static volatile int turn;

    private Floors() {
    }

    /**
     * The figures of one measurement.
     *
     * @param platformHandOffMicros one hand-off between two platform threads, µs
     * @param virtualHandOffMicros  one hand-off between two virtual threads, µs, or NaN on a JDK
     *                              without them
     * @param loopbackRoundTripMicros one loopback TCP round trip, µs
     */
    public record Figures(double platformHandOffMicros, double virtualHandOffMicros, double loopbackRoundTripMicros) {
    }

    /**
     * Measures each floor once after a warm-up.
     *
     * @param rounds hand-offs and round trips to time (the virtual hand-offs four times as many)
     * @return the figures
     * @throws InterruptedException if interrupted
     */
    public static Figures measure(int rounds) throws InterruptedException {
        handOff(false, rounds / 2);
        roundTrip(rounds / 4);
        double platform = handOff(false, rounds);
        double virtual = virtualThreads() ? handOff(true, 4 * rounds) : Double.NaN;
        return new Figures(platform, virtual, roundTrip(rounds));
    }

    /**
     * Prints figures as one line.
     *
     * @param out     where
     * @param figures what
     */
    public static void print(PrintWriter out, Figures figures) {
        out.printf(Locale.ROOT, "floors java=%d platform_handoff_us=%.2f virtual_handoff_us=%s loopback_rtt_us=%.2f%n",
                Runtime.version().feature(), figures.platformHandOffMicros(),
                Double.isNaN(figures.virtualHandOffMicros()) ? "none"
                        : String.format(Locale.ROOT, "%.2f", figures.virtualHandOffMicros()),
                figures.loopbackRoundTripMicros());
        out.flush();
    }

    private static boolean virtualThreads() {
        return Runtime.version().feature() >= 21;
    }

    /** Two threads that take turns {@code rounds} times each; µs per hand-off. */
    private static double handOff(boolean virtual, int rounds) throws InterruptedException {
        Thread[] pair = new Thread[2];
        Runnable first = () -> takeTurns(0, pair[1], rounds);
        Runnable second = () -> takeTurns(1, pair[0], rounds);
        pair[0] = thread(virtual, first);
        pair[1] = thread(virtual, second);
        turn = 0;
        long start = System.nanoTime();
        pair[0].start();
        pair[1].start();
        pair[0].join();
        pair[1].join();
        return (System.nanoTime() - start) / 1e3 / (2.0 * rounds);
    }

    private static void takeTurns(int mine, Thread other, int rounds) {
        for (int i = 0; i < rounds; i++) {
            while (turn != mine) {
                LockSupport.park();
            }
            turn = 1 - mine;
            LockSupport.unpark(other);
        }
    }

    private static Thread thread(boolean virtual, Runnable task) {
        if (!virtual) {
            return new Thread(task, "floors");
        }
        try {
            Object builder = Thread.class.getMethod("ofVirtual").invoke(null);
            Method unstarted = Class.forName("java.lang.Thread$Builder").getMethod("unstarted", Runnable.class);
            return (Thread) unstarted.invoke(builder, task);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("this JDK has no virtual threads", e);
        }
    }

    /** A time step's bytes out and a requests frame's bytes back, {@code rounds} times; µs per round trip. */
    private static double roundTrip(int rounds) {
        try (ServerSocket listener = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            listener.setSoTimeout(10_000);
            Thread echo = new Thread(() -> {
                try (Socket s = listener.accept()) {
                    s.setTcpNoDelay(true);
                    s.setSoTimeout(10_000);
                    DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
                    OutputStream out = s.getOutputStream();
                    byte[] step = new byte[STEP_BYTES];
                    byte[] requests = new byte[REQUESTS_BYTES];
                    for (int i = 0; i < rounds; i++) {
                        in.readFully(step);
                        out.write(requests);
                    }
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }, "floors-echo");
            echo.setDaemon(true);
            echo.start();
            try (Socket c = new Socket(InetAddress.getLoopbackAddress(), listener.getLocalPort())) {
                c.setTcpNoDelay(true);
                c.setSoTimeout(10_000);
                DataInputStream in = new DataInputStream(new BufferedInputStream(c.getInputStream()));
                OutputStream out = c.getOutputStream();
                byte[] step = new byte[STEP_BYTES];
                byte[] requests = new byte[REQUESTS_BYTES];
                long start = System.nanoTime();
                for (int i = 0; i < rounds; i++) {
                    out.write(step);
                    in.readFully(requests);
                }
                return (System.nanoTime() - start) / 1e3 / rounds;
            }
        } catch (IOException e) {
            throw new UncheckedIOException("the loopback round trip failed", e);
        }
    }
}
