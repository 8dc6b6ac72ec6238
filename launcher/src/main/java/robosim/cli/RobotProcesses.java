package robosim.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import robosim.params.RobotParameterFiles;
import robosim.protocol.RunSecret;

/** Starts robot programs in JVMs of their own, with this JVM's classpath, and stops them. */
public final class RobotProcesses {
    private RobotProcesses() {
    }

    /**
     * Starts {@code robosim robot CLASS NAME 127.0.0.1 PORT ARGS...} in a new JVM.
     *
     * @param className the robot program
     * @param name      the robot's name
     * @param port      the Environment's robot port on loopback
     * @param log       where its output goes
     * @param args      more arguments for the program
     * @return the process
     * @throws IOException if the JVM cannot be started
     */
    public static Process start(String className, String name, int port, Path log, String... args) throws IOException {
        return start(className, name, port, null, log, args);
    }

    /**
     * Starts {@code robosim robot CLASS NAME 127.0.0.1 PORT ARGS...} in a new JVM that presents a
     * run secret (through the environment variable {@value RunSecret#ENV}, which other users cannot read).
     *
     * @param className the robot program
     * @param name      the robot's name
     * @param port      the Environment's robot port on loopback
     * @param secret    the run's secret, or null to let the program find it
     * @param log       where its output goes
     * @param args      more arguments for the program
     * @return the process
     * @throws IOException if the JVM cannot be started
     */
    public static Process start(String className, String name, int port, String secret, Path log, String... args)
            throws IOException {
        return start(className, null, name, port, secret, log, List.of(args));
    }

    /**
     * Starts {@code robosim robot [--classpath PATH] CLASS NAME 127.0.0.1 PORT ARGS...} in a new JVM.
     *
     * @param className the robot program
     * @param classpath where its classes are besides RoboSim's, or null
     * @param name      the robot's name
     * @param port      the Environment's robot port on loopback
     * @param secret    the run's secret, or null to let the program find it
     * @param log       where its output goes
     * @param args      more arguments for the program
     * @return the process
     * @throws IOException if the JVM cannot be started
     */
    public static Process start(String className, String classpath, String name, int port, String secret, Path log,
                                List<String> args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(javaBinary(), "-Djava.awt.headless=true",
                "-Drobosim.root=" + RobotParameterFiles.root(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName(), "robot"));
        if (classpath != null) {
            cmd.addAll(List.of("--classpath", classpath));
        }
        cmd.addAll(List.of(className, name, "127.0.0.1", Integer.toString(port)));
        cmd.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile());
        if (secret != null) {
            pb.environment().put(RunSecret.ENV, secret);
        }
        return pb.start();
    }

    /**
     * Waits a little for each process to end by itself, then ends it.
     *
     * @param processes the processes
     * @throws InterruptedException if interrupted
     */
    public static void stop(List<Process> processes) throws InterruptedException {
        for (Process p : processes) {
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroy();
                if (!p.waitFor(5, TimeUnit.SECONDS)) {
                    p.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
                }
            }
        }
    }

    /** @return this JVM's java command, for the JVMs it starts */
    static String javaBinary() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }
}
