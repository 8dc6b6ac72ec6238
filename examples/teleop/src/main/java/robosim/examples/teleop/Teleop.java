package robosim.examples.teleop;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * A keyboard teleop: reads one command a line (type it and press Enter) and drives a Pioneer by
 * it. Each command takes effect at the next step; {@code wait N} lets N steps pass, so a file or a
 * pipe of commands drives the same run every time.
 *
 * <table>
 * <caption>Commands</caption>
 * <tr><th>line</th><th>does</th></tr>
 * <tr><td>{@code w} / {@code s}</td><td>100 mm/s faster / slower (from -300 to 600 mm/s)</td></tr>
 * <tr><td>{@code a} / {@code d}</td><td>turn 10 deg/s more to the left / right (at most 50 deg/s)</td></tr>
 * <tr><td>{@code x}</td><td>stop</td></tr>
 * <tr><td>{@code wait N}</td><td>let N steps pass (1 to 100000)</td></tr>
 * <tr><td>{@code q}</td><td>stop and leave the run (so does the end of the input)</td></tr>
 * </table>
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.teleop.Teleop NAME HOST PORT}, or with
 * commands from a file: {@code ... Teleop r1 localhost 5000 < commands.txt}.
 */
public final class Teleop {
    /** The help line, also printed after a command that is not one. */
    public static final String COMMANDS = "w faster, s slower, a left, d right, x stop, wait N steps, q quit";
    private static final double VEL_STEP = 100;
    private static final double ROT_STEP = 10;

    private final ArRobot robot;
    private final PrintStream out;
    private double vel;
    private double rotVel;

    /**
     * @param robot a connected robot
     * @param out   where the robot's speeds and complaints about commands are printed
     */
    public Teleop(ArRobot robot, PrintStream out) {
        this.robot = robot;
        this.out = out;
    }

    /**
     * Drives a robot by the commands on standard input.
     *
     * @param args NAME HOST PORT
     */
    public static void main(String[] args) {
        if (args.length != 3) {
            throw new IllegalArgumentException("usage: Teleop NAME HOST PORT");
        }
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("robot " + args[0] + " could not connect: " + robot.getConnectionError());
        }
        robot.enableMotors(); // a Pioneer's motors are disabled when its program connects, as in ARIA
        System.out.println("teleop " + args[0] + ": " + COMMANDS);
        new Teleop(robot, System.out).run(new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)));
        robot.disconnect();
    }

    /**
     * Applies commands until {@code q}, the end of the input or the end of the run; then stops the
     * robot.
     *
     * @param in the commands, one a line
     */
    public void run(BufferedReader in) {
        try {
            String line;
            while (robot.isConnected() && (line = in.readLine()) != null) {
                if (!apply(line.trim())) {
                    break;
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("teleop: the commands could not be read: " + e.getMessage(), e);
        }
        robot.stop();
    }

    /** @return false after {@code q} */
    private boolean apply(String command) {
        int steps = 1;
        switch (command) {
            case "" -> {
                return true;
            }
            case "q" -> {
                return false;
            }
            case "w" -> vel = Math.min(600, vel + VEL_STEP);
            case "s" -> vel = Math.max(-300, vel - VEL_STEP);
            case "a" -> rotVel = Math.min(50, rotVel + ROT_STEP);
            case "d" -> rotVel = Math.max(-50, rotVel - ROT_STEP);
            case "x" -> {
                vel = 0;
                rotVel = 0;
            }
            default -> {
                steps = waitSteps(command);
                if (steps < 0) {
                    out.println("teleop: '" + command + "' is not a command: " + COMMANDS);
                    return true;
                }
            }
        }
        robot.setVel(vel);
        robot.setRotVel(rotVel);
        if (steps == 1) {
            out.printf("vel %.0f mm/s, rotVel %.0f deg/s, pose %s%n", vel, rotVel, robot.getPose());
        }
        ArUtil.sleep((long) steps * robot.getStepMs());
        return true;
    }

    /** @return N of a {@code wait N} with N from 1 to 100000, else -1 */
    private static int waitSteps(String command) {
        if (!command.matches("wait\\s+\\d{1,6}")) {
            return -1;
        }
        int n = Integer.parseInt(command.substring(4).trim());
        return n >= 1 && n <= 100_000 ? n : -1;
    }
}
