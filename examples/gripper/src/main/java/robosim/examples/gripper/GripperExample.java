package robosim.examples.gripper;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import robosim.aria.ArGripper;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * ARIA's gripperExample (examples/gripperExample.cpp): a Pioneer's 2-DOF gripper worked from the
 * keyboard with ARIA's keys, its state logged as ARIA's {@code logState} words it. ARIA's example
 * reads single keys and drives with the arrow keys; this one reads one command a line (type it and
 * press Enter), drives with {@code move} and {@code turn}, and prints the gripper's state whenever
 * it changes, so a file of commands gives the same run every time.
 *
 * <table>
 * <caption>Commands</caption>
 * <tr><th>line</th><th>does</th></tr>
 * <tr><td>{@code u} / {@code d}</td><td>lift up / down</td></tr>
 * <tr><td>{@code o} / {@code c}</td><td>open / close the paddles</td></tr>
 * <tr><td>{@code s}</td><td>stop the paddles and the lift ({@code gripperHalt})</td></tr>
 * <tr><td>{@code move N}</td><td>drive N mm (negative backwards) and wait until done</td></tr>
 * <tr><td>{@code turn N}</td><td>turn N degrees (counter-clockwise positive) and wait until done</td></tr>
 * <tr><td>{@code wait N}</td><td>let N steps pass (1 to 100000)</td></tr>
 * <tr><td>{@code q}</td><td>leave the run (so does the end of the input)</td></tr>
 * </table>
 *
 * <p>Run it as {@code bin/robosim robot robosim.examples.gripper.GripperExample NAME HOST PORT}
 * for a robot whose parameter file has a gripper ({@code p3dx-gripper}).
 */
public final class GripperExample {
    /** The help line, also printed after a command that is not one. */
    public static final String COMMANDS = "u lift up, d lift down, o open, c close, s stop, move N mm, turn N deg, "
            + "wait N steps, q quit";
    /** Steps a {@code move} or {@code turn} may take before it is given up. */
    private static final int MOTION_STEPS = 600;

    private final ArRobot robot;
    private final ArGripper gripper;
    private final PrintStream out;
    private String shown = "";

    /**
     * @param robot   a connected robot
     * @param gripper its gripper
     * @param out     where the gripper's state and complaints about commands are printed
     */
    public GripperExample(ArRobot robot, ArGripper gripper, PrintStream out) {
        this.robot = robot;
        this.gripper = gripper;
        this.out = out;
    }

    /**
     * Connects a Pioneer 3-DX with a gripper and works it by the commands on standard input.
     *
     * @param args NAME HOST PORT
     */
    public static void main(String[] args) {
        if (args.length != 3) {
            throw new IllegalArgumentException("usage: GripperExample NAME HOST PORT");
        }
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx-gripper");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("gripperExample: could not connect to the robot: "
                    + robot.getConnectionError());
        }
        robot.enableMotors();
        ArGripper gripper = new ArGripper(robot);
        GripperExample example = new GripperExample(robot, gripper, System.out);
        if (!example.start()) {
            robot.disconnect();
            System.exit(1);
        }
        System.out.println("gripperExample: " + COMMANDS);
        example.run(new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)));
        robot.disconnect();
    }

    /**
     * Waits for the robot's first state, prints the gripper's type and state as ARIA's example does.
     *
     * @return false when the robot has no gripper
     */
    public boolean start() {
        ArUtil.sleep(robot.getStepMs());
        ArGripper.Type type = gripper.getType();
        out.println("gripperExample: GripperType=" + type);
        show();
        if (type == ArGripper.Type.NOGRIPPER) {
            out.println("gripperExample: Error: Robot does not have a gripper. Exiting.");
            return false;
        }
        return true;
    }

    /**
     * Applies commands until {@code q}, the end of the input or the end of the run.
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
            throw new UncheckedIOException("gripperExample: the commands could not be read: " + e.getMessage(), e);
        }
        robot.stop();
    }

    /** @return false after {@code q} */
    private boolean apply(String command) {
        String[] words = command.split("\\s+");
        switch (words[0]) {
            case "" -> {
                return true;
            }
            case "q" -> {
                return false;
            }
            case "u" -> say("Moving gripper lift up...", gripper.liftUp());
            case "d" -> say("Moving gripper lift down...", gripper.liftDown());
            case "o" -> say("Opening gripper...", gripper.gripOpen());
            case "c" -> say("Closing gripper...", gripper.gripClose());
            case "s" -> say("Stopping gripper...", gripper.gripperHalt());
            case "move", "turn", "wait" -> {
                Integer n = words.length == 2 && words[1].matches("-?\\d{1,6}") ? Integer.parseInt(words[1]) : null;
                if (n == null || words[0].equals("wait") && n < 1) {
                    out.println("gripperExample: '" + command + "' needs a whole number: " + COMMANDS);
                    return true;
                }
                motion(words[0], n);
                return true;
            }
            default -> {
                out.println("gripperExample: '" + command + "' is not a command: " + COMMANDS);
                return true;
            }
        }
        step(1);
        return true;
    }

    private void say(String what, boolean sent) {
        out.println("gripperExample: " + what + (sent ? "" : " (not sent: the robot is not connected)"));
    }

    private void motion(String kind, int n) {
        if (kind.equals("wait")) {
            step(n);
            return;
        }
        if (kind.equals("move")) {
            robot.move(n);
        } else {
            robot.setDeltaHeading(n);
        }
        step(2);
        for (int i = 0; i < MOTION_STEPS && robot.isConnected()
                && !(kind.equals("move") ? robot.isMoveDone(1) : robot.isHeadingDone(1)); i++) {
            step(1);
        }
        out.println("gripperExample: at " + robot.getPose());
    }

    /** Lets steps pass one by one, printing the gripper's state whenever it changes. */
    private void step(int steps) {
        for (int i = 0; i < steps && robot.isConnected(); i++) {
            ArUtil.sleep(robot.getStepMs());
            show();
        }
    }

    private void show() {
        String state = gripper.stateLine();
        if (!state.equals(shown)) {
            out.println(state);
            shown = state;
        }
    }
}
