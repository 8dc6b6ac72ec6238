package robosim.it;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import robosim.cli.Background;

/**
 * A JVM a test started with the test's classpath, maybe behind a prefix such as
 * {@code ip netns exec NS}: its output (standard output and error together) is kept line by line,
 * a line can be waited for, and {@link #close()} ends the JVM if it is still running. Every wait
 * is bounded.
 */
final class JvmProcess implements AutoCloseable {
    /** Put in the queue when the output ends, so that a wait for a line ends with it. */
    private static final String END = new String("end of output");

    private final String name;
    private final Process process;
    private final List<String> lines = new ArrayList<>();
    private final BlockingQueue<String> unread = new LinkedBlockingQueue<>();

    private JvmProcess(String name, Process process) {
        this.name = name;
        this.process = process;
        Background.run(name + "-output", this::readOutput);
    }

    /**
     * Starts {@code PREFIX... java -cp CLASSPATH MAIN ARGS...}.
     *
     * @param name        what to call the JVM in messages
     * @param prefix      what runs the JVM, such as {@code ip netns exec NS}, or nothing
     * @param environment variables added to this JVM's environment
     * @param mainClass   the class whose {@code main} runs
     * @param args        its arguments
     * @return the running JVM
     * @throws IOException if it cannot be started
     */
    static JvmProcess start(String name, List<String> prefix, Map<String, String> environment, String mainClass,
            List<String> args) throws IOException {
        List<String> cmd = new ArrayList<>(prefix);
        cmd.addAll(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-Drobosim.root=" + LocalEnvironment.root(),
                "-cp", System.getProperty("java.class.path"), mainClass));
        cmd.addAll(args);
        ProcessBuilder builder = new ProcessBuilder(cmd).redirectErrorStream(true);
        builder.environment().putAll(environment);
        return new JvmProcess(name, builder.start());
    }

    private void readOutput() {
        InputStreamReader output = new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8);
        try (BufferedReader in = new BufferedReader(output)) {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                synchronized (lines) {
                    lines.add(line);
                }
                unread.add(line);
            }
        } catch (IOException e) {
            synchronized (lines) {
                lines.add("(reading the output failed: " + e + ")");
            }
        } finally {
            unread.add(END);
        }
    }

    /**
     * Waits for a line that starts with the given text, after the lines an earlier call returned.
     *
     * @param start   how the line starts
     * @param timeout how long to wait
     * @return the line
     * @throws TimeoutException if no such line came in time or the output ended first; the message
     *                          holds the output so far
     */
    String awaitLine(String start, Duration timeout) throws TimeoutException, InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            String line = unread.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
            if (line == null || line == END) {
                if (line == END) {
                    unread.add(END);
                }
                throw new TimeoutException(name + " printed no line starting \"" + start + "\" "
                        + (line == null ? "within " + timeout.toSeconds() + " s" : "before its output ended")
                        + "; its output:\n" + output());
            }
            if (line.startsWith(start)) {
                return line;
            }
        }
    }

    /**
     * Waits for the JVM to end by itself.
     *
     * @param timeout how long to wait
     * @return its exit code
     * @throws TimeoutException if it is still running then (it is left running for {@link #close()})
     */
    int awaitExit(Duration timeout) throws TimeoutException, InterruptedException {
        if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new TimeoutException(name + " still runs after " + timeout.toSeconds() + " s; its output:\n"
                    + output());
        }
        return process.exitValue();
    }

    /** @return every line printed so far, one per line */
    String output() {
        synchronized (lines) {
            return String.join("\n", lines);
        }
    }

    /** @return the lines printed so far */
    List<String> lines() {
        synchronized (lines) {
            return List.copyOf(lines);
        }
    }

    /**
     * Ends the JVM if it is still running, and waits a little for it to go. An interrupted thread
     * (a test past its timeout) still ends it, without the wait.
     */
    @Override
    public void close() {
        if (process.isAlive()) {
            process.destroyForcibly();
            try {
                process.waitFor(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
