package robosim.panel.model;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * A robot program the panel's "add robot" starts in a JVM of its own: a class (from RoboSim's
 * classpath or a jar), the robot's name and, if the user gave one, the pose to place it at once it
 * has joined.
 *
 * @param program   the program's class, with a static {@code main(String[])}
 * @param jar       a jar (or folder) holding it, or null when it is on RoboSim's classpath
 * @param name      the robot's name in the world
 * @param placement the move request that places it, or null to leave it at its start pose
 */
public record RobotLaunch(String program, Path jar, String name, Request placement) {
    /**
     * Reads the fields of the "add robot" form.
     *
     * @param program the class name as typed
     * @param jar     the jar as typed (empty: none)
     * @param name    the robot's name as typed
     * @param x       x, mm, as typed (all three empty: no placement)
     * @param y       y, mm, as typed
     * @param th      heading, degrees, as typed
     * @return the launch
     * @throws IllegalArgumentException naming the field, the value and the rule
     */
    public static RobotLaunch parse(String program, String jar, String name, String x, String y, String th) {
        String p = program == null ? "" : program.trim();
        if (!p.matches("[A-Za-z_$][A-Za-z0-9_$]*(\\.[A-Za-z_$][A-Za-z0-9_$]*)*")) {
            throw new IllegalArgumentException("Program: a Java class name such as robosim.examples.wander.Wander, got '"
                    + program + "'");
        }
        Path j = null;
        if (jar != null && !jar.isBlank()) {
            j = Path.of(jar.trim());
            if (!Files.exists(j)) {
                throw new IllegalArgumentException("Jar: no such file or folder: " + j);
            }
        }
        String n = name == null ? "" : name.trim();
        if (!n.matches("[A-Za-z0-9_.\\-]{1,64}")) {
            throw new IllegalArgumentException("Name: 1 to 64 letters, digits, '_', '.' or '-', got '" + name + "'");
        }
        boolean anyPose = !blank(x) || !blank(y) || !blank(th);
        Request place = null;
        if (anyPose) {
            place = Request.move(n, blank(x) ? "" : x, blank(y) ? "" : y, blank(th) ? "0" : th);
        }
        return new RobotLaunch(p, j, n, place);
    }

    private static boolean blank(String s) {
        return s == null || s.isBlank();
    }

    /**
     * @param host      the Environment's host, as robots reach it
     * @param robotPort its robot port
     * @return the arguments of {@code robosim robot}, from the subcommand's name on
     */
    public List<String> robotArguments(String host, int robotPort) {
        List<String> a = new ArrayList<>(List.of("robot"));
        if (jar != null) {
            a.add("--cp");
            a.add(jar.toString());
        }
        a.addAll(List.of(program, name, host, Integer.toString(robotPort)));
        return a;
    }

    /** @return the request that places the robot, if the user gave a pose */
    public Optional<Request> placementRequest() {
        return Optional.ofNullable(placement);
    }
}
