package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.cli.Main;

/**
 * The README tour's start, run as a user runs it, while the machine is kept busy on purpose:
 * {@code src/test/scripts/start-orders.sh} starts an Environment and its two robots, each a JVM of
 * its own with the tour's command lines, in every order the tour allows (the Environment first or
 * the robots first, 0 to 3 s apart), two cases at a time, and with a display a ControlPanel attached
 * before its Environment, and an ARIA client ({@link AriaHandshakeClient}, ARIA's patience for each
 * answer) on a Pioneer port while the run waits for its other robot. Meanwhile twice as many processes as the machine has cores spin. Every
 * case must start, run its steps and end with no connection refused, and every order must give
 * the same run. The launcher is this JVM's classpath in a script of the same shape as
 * {@code bin/robosim}, which would otherwise build the project again.
 */
@Timeout(value = 8, unit = TimeUnit.MINUTES)
class StartOrdersUnderLoadTest {
    @TempDir
    Path dir;

    @Test
    void everyStartOrderOfTheToursRunStartsTheSameRunWithNoRefusalWhileTheMachineIsBusy() throws Exception {
        Path launcher = launcher();
        boolean display = System.getenv("DISPLAY") != null && !System.getenv("DISPLAY").isBlank();
        if (!display) {
            System.err.println("StartOrdersUnderLoadTest: no DISPLAY, so the ControlPanel case is SKIPPED;"
                    + " run under xvfb-run (as .ci/run does) to include it");
        }
        int cases = 7 + (display ? 1 : 0);
        List<String> cmd = new ArrayList<>(List.of("bash",
                LocalEnvironment.root().resolve("integration-tests/src/test/scripts/start-orders.sh").toString(),
                dir.resolve("out").toString()));
        // the Pioneer case comes last: its third port and the one after it are the two robots' Pioneer ports
        for (int port : freePorts(3 * cases)) {
            cmd.add(Integer.toString(port));
        }
        Path output = dir.resolve("start-orders.out");
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(output.toFile());
        pb.environment().put("ROBOSIM", launcher.toString());
        pb.environment().put("PIONEER_CLIENT", java("aria-client", AriaHandshakeClient.class.getName()).toString());
        pb.environment().put("ROBOSIM_TOKEN_DIR", dir.resolve("tokens").toString());
        pb.environment().put("CASE_TIMEOUT", "240");
        // two cases at once: six JVMs starting beside the spinners
        pb.environment().put("TOGETHER", "2");
        pb.environment().remove("ROBOSIM_TOKEN");
        if (display) {
            pb.environment().put("PANEL", "1");
        }
        List<Process> load = busy(2 * Runtime.getRuntime().availableProcessors());
        Process script = pb.start();
        try {
            boolean ended = script.waitFor(6, TimeUnit.MINUTES);
            String out = Files.readString(output, StandardCharsets.UTF_8);
            System.err.println("start orders under load:\n" + out);
            assertTrue(ended, "the cases ended within 6 minutes:\n" + out);
            assertEquals(0, script.exitValue(), out);
            assertEquals(cases, out.lines().filter(l -> l.startsWith("case ") && l.contains(" ok: ")).count(), out);
        } finally {
            script.descendants().forEach(ProcessHandle::destroyForcibly);
            script.destroyForcibly();
            for (Process p : load) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
            }
            for (Process p : load) {
                p.waitFor(10, TimeUnit.SECONDS);
            }
        }
    }

    /** @return a script that runs the launcher on this JVM's classpath, as {@code bin/robosim} runs it */
    private Path launcher() throws IOException {
        return java("robosim", Main.class.getName());
    }

    /** @return a script named {@code name} that runs a main class on this JVM's classpath with its arguments */
    private Path java(String name, String mainClass) throws IOException {
        Path script = dir.resolve(name);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Files.writeString(script, "#!/usr/bin/env bash\nexec '" + java + "' -Djava.awt.headless=true '-Drobosim.root="
                + LocalEnvironment.root() + "' -cp '" + System.getProperty("java.class.path") + "' " + mainClass
                + " \"$@\"\n");
        assertTrue(script.toFile().setExecutable(true));
        return script;
    }

    /**
     * @return processes that spin on a core each until destroyed (each is the shell itself, so that
     *         destroying it stops the spinning); should this JVM die first, each stops by itself
     *         once it sees the JVM gone
     */
    private static List<Process> busy(int count) throws IOException {
        List<Process> spinners = new ArrayList<>();
        long jvm = ProcessHandle.current().pid();
        for (int i = 0; i < count; i++) {
            spinners.add(new ProcessBuilder("sh", "-c", "while kill -0 " + jvm + " 2>/dev/null; do i=0;"
                    + " while [ $i -lt 20000 ]; do i=$((i + 1)); done; done")
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start());
        }
        return spinners;
    }

    /**
     * @return ports free now on loopback, all different, the last of which has a free port after it
     *         too (also different from the others)
     */
    private static List<Integer> freePorts(int count) throws IOException {
        List<ServerSocket> held = new ArrayList<>();
        try {
            List<Integer> ports = new ArrayList<>();
            for (int i = 0; i < count - 1; i++) {
                ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
                held.add(s);
                ports.add(s.getLocalPort());
            }
            for (int tries = 0; tries < 100; tries++) {
                ServerSocket last = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
                held.add(last);
                try {
                    held.add(new ServerSocket(last.getLocalPort() + 1, 1, InetAddress.getLoopbackAddress()));
                    ports.add(last.getLocalPort());
                    return ports;
                } catch (IOException | IllegalArgumentException taken) {
                    // the next port is taken (or past 65535): held on to, so that it is not given again
                }
            }
            throw new IOException("no free port with a free port after it in 100 tries");
        } finally {
            for (ServerSocket s : held) {
                s.close();
            }
        }
    }
}
