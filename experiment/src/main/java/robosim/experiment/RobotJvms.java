package robosim.experiment;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * Starts a robot program in a JVM of its own, for programs whose link is {@code jvm}: the launcher
 * gives its own way ({@code robosim robot CLASS NAME 127.0.0.1 PORT ARGS...}).
 */
@FunctionalInterface
public interface RobotJvms {
    /**
     * @param className the program
     * @param robot     the robot's name
     * @param port      the Environment's robot port on loopback
     * @param secret    the run's secret, for the JVM to present
     * @param log       where its output goes
     * @param args      the program's arguments after the name, host and port
     * @return the process
     * @throws IOException if it cannot be started
     */
    Process start(String className, String robot, int port, String secret, Path log, List<String> args)
            throws IOException;
}
