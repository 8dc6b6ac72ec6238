package robosim.env.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A robot asked for on the command line ({@code --robot TYPE[:NAME]}), to be placed at the
 * world's next home: {@code type} names a parameter file (a shipped name such as {@code p3dx}, or a
 * path), and {@code name} is what the robot connects under.
 *
 * @param type the parameter file: a shipped name or a path
 * @param name the robot's name, or {@code null} for the default, {@code TYPE_N}
 */
public record RobotToPlace(String type, String name) {

    /**
     * Reads {@code TYPE} or {@code TYPE:NAME}. The name follows the last colon, so a path with a
     * drive letter ({@code C:\robots\p3dx.p}) needs a name after it.
     *
     * @param text the option's value
     * @return the robot to place
     * @throws IllegalArgumentException if the type or the name is empty
     */
    public static RobotToPlace parse(String text) {
        int colon = text.lastIndexOf(':');
        String type = colon < 0 ? text : text.substring(0, colon);
        String name = colon < 0 ? null : text.substring(colon + 1);
        if (type.isBlank()) {
            throw new IllegalArgumentException("'" + text + "' was supplied for --robot: it must be TYPE or TYPE:NAME"
                    + " with a TYPE such as p3dx");
        }
        if (name != null && name.isBlank()) {
            throw new IllegalArgumentException("'" + text + "' was supplied for --robot: the NAME after ':' is empty"
                    + " (leave out ':' for the default name)");
        }
        return new RobotToPlace(type, name);
    }

    /**
     * The names the robots connect under: a name given, or else {@code TYPE_N}, the type's file
     * name without its extension and folder, numbered from 1 in order among the robots of that
     * type ({@code p3dx_1}, {@code p3dx_2}, {@code p3at_1}).
     *
     * @param toPlace the robots to place, in order
     * @return their names, in the same order
     */
    public static List<String> names(List<RobotToPlace> toPlace) {
        Map<String, Integer> counts = new HashMap<>();
        List<String> names = new ArrayList<>();
        for (RobotToPlace r : toPlace) {
            String base = r.baseType();
            int n = counts.merge(base, 1, Integer::sum);
            names.add(r.name != null ? r.name : base + "_" + n);
        }
        return names;
    }

    /** @return the type's file name without folder and extension: {@code p3dx} for {@code ../robots/p3dx.p} */
    public String baseType() {
        String base = type.replace('\\', '/');
        base = base.substring(base.lastIndexOf('/') + 1);
        int dot = base.lastIndexOf('.');
        return dot > 0 ? base.substring(0, dot) : base;
    }

    @Override
    public String toString() {
        return name == null ? type : type + ":" + name;
    }
}
