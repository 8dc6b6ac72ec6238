package robosim.it;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A TCP relay that adds latency and jitter, for machines whose kernel has no {@code tc netem}: it
 * accepts connections on a port and joins each to a target address, and every chunk it reads, in
 * either direction, is written on after a delay of {@code delay ± jitter} ms drawn from a seeded
 * random stream. A chunk never overtakes the one before it (its release time is at least the
 * previous one's), so the bytes keep their order, as TCP keeps them over a jittery link.
 *
 * <p>It runs as a JVM of its own, in the network namespace between the robots' and the
 * Environment's: {@code DelayRelay LISTEN_PORT TARGET_HOST TARGET_PORT DELAY_MS JITTER_MS SEED}.
 * Once it listens it prints {@code DelayRelay: listening on port N}; it runs until it is killed or
 * its standard input ends, which happens when the JVM that started it ends, even if it was killed.
 */
final class DelayRelay {
    private static final int CHUNK = 64 * 1024;

    private DelayRelay() {
    }

    /** A chunk read, and when it may be written on. */
    private record Chunk(byte[] bytes, long releaseNanos) { }

    /**
     * Runs the relay.
     *
     * @param args LISTEN_PORT (0: any free port) TARGET_HOST TARGET_PORT DELAY_MS JITTER_MS SEED
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 6) {
            throw new IllegalArgumentException(
                    "usage: DelayRelay LISTEN_PORT TARGET_HOST TARGET_PORT DELAY_MS JITTER_MS SEED");
        }
        InetSocketAddress target = new InetSocketAddress(args[1], Integer.parseInt(args[2]));
        long delay = Long.parseLong(args[3]);
        long jitter = Long.parseLong(args[4]);
        if (jitter < 0 || jitter > delay) {
            throw new IllegalArgumentException(jitter + " was supplied for JITTER_MS: it must be 0 to DELAY_MS ("
                    + delay + ")");
        }
        SplittableRandom seeds = new SplittableRandom(Long.parseLong(args[5]));
        Thread watchdog = new Thread(() -> {
            try {
                System.in.transferTo(OutputStream.nullOutputStream());
            } catch (IOException e) {
                // the parent's end is broken: it has gone too
            }
            System.exit(0);
        }, "relay-parent-watch");
        watchdog.setDaemon(true);
        watchdog.start();
        try (ServerSocket server = new ServerSocket(Integer.parseInt(args[0]))) {
            System.out.println("DelayRelay: listening on port " + server.getLocalPort() + ", to " + target
                    + ", delay " + delay + " ms, jitter " + jitter + " ms");
            System.out.flush();
            while (true) {
                Socket in = server.accept();
                Socket out = new Socket();
                try {
                    out.connect(target, 10_000);
                } catch (IOException e) {
                    System.out.println("DelayRelay: cannot reach " + target + ": " + e);
                    in.close();
                    continue;
                }
                in.setTcpNoDelay(true);
                out.setTcpNoDelay(true);
                AtomicInteger directions = new AtomicInteger(2);
                pipe(in, out, directions, delay, jitter, seeds.split());
                pipe(out, in, directions, delay, jitter, seeds.split());
            }
        }
    }

    /**
     * Carries one direction of a connection on two threads: one reads, one writes when due. The
     * direction that ends last closes both sockets.
     */
    private static void pipe(Socket from, Socket to, AtomicInteger directions, long delayMs, long jitterMs,
            SplittableRandom random) {
        BlockingQueue<Chunk> queue = new LinkedBlockingQueue<>();
        Thread reader = new Thread(() -> {
            long last = 0;
            try {
                InputStream in = from.getInputStream();
                byte[] buffer = new byte[CHUNK];
                for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                    long latency = delayMs + (jitterMs == 0 ? 0 : random.nextLong(-jitterMs, jitterMs + 1));
                    last = Math.max(last, System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(latency));
                    queue.add(new Chunk(Arrays.copyOf(buffer, n), last));
                }
            } catch (IOException e) {
                // the connection was closed or reset: end this direction as the writer drains it
            }
            queue.add(new Chunk(null, last));
        }, "relay-read");
        Thread writer = new Thread(() -> {
            try {
                OutputStream out = to.getOutputStream();
                for (Chunk c = queue.take(); c.bytes() != null; c = queue.take()) {
                    long wait = c.releaseNanos() - System.nanoTime();
                    if (wait > 0) {
                        // the link's latency itself, not a wait for another thread
                        TimeUnit.NANOSECONDS.sleep(wait);
                    }
                    out.write(c.bytes());
                    out.flush();
                }
                to.shutdownOutput();
                if (directions.decrementAndGet() > 0) {
                    return;
                }
            } catch (IOException | InterruptedException e) {
                // a broken direction breaks the connection
            }
            closeQuietly(from);
            closeQuietly(to);
        }, "relay-write");
        reader.start();
        writer.start();
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException e) {
            // already closed
        }
    }
}
