package robosim.env.net;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.RecordComponent;
import java.util.Objects;
import robosim.protocol.RobotParameters;

/**
 * Where the parameters a robot program sends first differ from those of the world's parameter
 * file, for the one line the Environment logs when a robot's hello overrides its world file.
 */
final class ParameterDifference {
    private ParameterDifference() {
    }

    /**
     * @param world   what the world's {@code <robot params=...>} file says
     * @param program what the robot program sent in its hello
     * @return the first field that differs, as {@code "maxVelocity 2200.0 in the world's file, 1500.0
     *         in the program's"}, or null if the two are equal
     */
    static String first(RobotParameters world, RobotParameters program) {
        return first(world, program, "the world's file");
    }

    /**
     * @param held    the parameters held now
     * @param program what the robot program sent in its hello
     * @param whose   whose the held parameters are, for the text, such as {@code "its body"}
     * @return the first field that differs, as {@code "maxVelocity 2200.0 in its body, 1500.0 in the
     *         program's"}, or null if the two are equal
     */
    static String first(RobotParameters held, RobotParameters program, String whose) {
        RobotParameters world = held;
        if (world.equals(program)) {
            return null;
        }
        for (RecordComponent c : RobotParameters.class.getRecordComponents()) {
            Object w = value(c, world);
            Object p = value(c, program);
            if (!Objects.equals(w, p)) {
                return c.getName() + " " + shown(w) + " in " + whose + ", " + shown(p) + " in the program's";
            }
        }
        return null;
    }

    private static Object value(RecordComponent c, RobotParameters p) {
        try {
            return c.getAccessor().invoke(p);
        } catch (IllegalAccessException | InvocationTargetException e) {
            throw new IllegalStateException("cannot read " + c.getName() + " of a RobotParameters", e);
        }
    }

    /** A sonar list can run to thousands of characters; a log line keeps its first 200. */
    private static String shown(Object value) {
        String text = String.valueOf(value);
        return text.length() > 200 ? text.substring(0, 200) + "..." : text;
    }
}
