package robosim.it;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import robosim.cli.Main;

/**
 * {@code bin/robosim} in a JVM of its own, with this JVM's classpath: its standard output and error,
 * line by line, as they come. Every wait is bounded; closing it ends the JVM if it still runs.
 */
final class LauncherJvm implements AutoCloseable {
    private final Process process;
    private final Thread reader;
    private final List<String> lines = new ArrayList<>();

    /** @param args the launcher's command line, for example {@code robot CLASS NAME HOST PORT} */
    LauncherJvm(String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-Drobosim.root=" + LocalEnvironment.root(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName()));
        cmd.addAll(List.of(args));
        process = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        reader = new Thread(this::read, "output-of-" + args[0]);
        reader.setDaemon(true);
        reader.start();
    }

    private void read() {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(),
                StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                synchronized (this) {
                    lines.add(line);
                    notifyAll();
                }
            }
        } catch (IOException e) {
            // the process ended
        }
    }

    /**
     * @return the first line that matches, once it has come
     * @throws AssertionError if none comes within the wait
     */
    synchronized String awaitLine(Predicate<String> matches, long seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (true) {
            for (String line : lines) {
                if (matches.test(line)) {
                    return line;
                }
            }
            long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (left <= 0) {
                throw new AssertionError("no such line within " + seconds + " s; the output so far:\n"
                        + String.join("\n", lines));
            }
            wait(left);
        }
    }

    /**
     * @return the exit code, once the JVM has ended and all its output is read
     * @throws AssertionError if the JVM has not ended within the wait
     */
    int awaitExit(long seconds) throws InterruptedException {
        if (!process.waitFor(seconds, TimeUnit.SECONDS)) {
            throw new AssertionError("still running after " + seconds + " s; the output so far:\n" + output());
        }
        reader.join(TimeUnit.SECONDS.toMillis(10));
        return process.exitValue();
    }

    /** @return every line so far (all of them once the JVM has ended and its output is read) */
    synchronized List<String> lines() {
        return new ArrayList<>(lines);
    }

    /** @return the output so far, for failure messages */
    String output() {
        return String.join("\n", lines());
    }

    /** Writes text to the JVM's standard input and closes it, as a pipe from a file would. */
    void input(String text) throws IOException {
        try (var in = process.getOutputStream()) {
            in.write(text.getBytes(StandardCharsets.UTF_8));
        }
    }

    /** Ends the JVM at once, as a crash or {@code kill -9} would. */
    void kill() throws InterruptedException {
        process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
    }

    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            kill();
        }
    }
}
