package robosim.protocol;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The kinds of robot RoboSim simulates, each with its traits: the name world files and hellos give
 * it, the API its programs are written against, the parameter file a program uses when it names
 * none, and whether it has a motor switch. Every part of RoboSim that asks what a kind is or has
 * asks here; adding a kind is a constant here, its API module and its parameter file (see
 * docs/EXTENDING.md).
 */
public enum RobotKind {
    /** A Pioneer (ActivMedia/MobileRobots), programmed through ARIA's {@code ArRobot}. */
    PIONEER("pioneer", "aria-api", "robosim.aria.ArRobot", "p3dx", true),
    /** A Nomadic Scout, programmed through the Nomadic API ({@code Scout}). */
    SCOUT("scout", "scout-api", "robosim.scout.Scout", "scout", false);

    private final String id;
    private final String apiModule;
    private final String apiClass;
    private final String defaultParameters;
    private final boolean motorSwitch;

    RobotKind(String id, String apiModule, String apiClass, String defaultParameters, boolean motorSwitch) {
        this.id = id;
        this.apiModule = apiModule;
        this.apiClass = apiClass;
        this.defaultParameters = defaultParameters;
        this.motorSwitch = motorSwitch;
    }

    /** @return the name world files ({@code <robot type=...>}) and hellos give the kind */
    public String id() {
        return id;
    }

    /** @return the Maven module of the API its programs are written against */
    public String apiModule() {
        return apiModule;
    }

    /** @return the class a program of this kind makes its robot from */
    public String apiClass() {
        return apiClass;
    }

    /**
     * @return the shipped parameter file (as {@code robosim.params.RobotParameterFiles} resolves a
     *         name) a program of this kind uses when it names none
     */
    public String defaultParameters() {
        return defaultParameters;
    }

    /**
     * @return whether the robot has a motor switch: its motors start disabled (unless the world says
     *         otherwise) and motion waits for a program to enable them, as on a Pioneer; a Scout has
     *         none and is always ready to move
     */
    public boolean hasMotorSwitch() {
        return motorSwitch;
    }

    /** @return every kind's name, in the order of the constants */
    public static List<String> ids() {
        return Arrays.stream(values()).map(RobotKind::id).toList();
    }

    /**
     * @param id a kind's name, in any case
     * @return the kind, if there is one of that name
     */
    public static Optional<RobotKind> of(String id) {
        if (id == null) {
            return Optional.empty();
        }
        String wanted = id.toLowerCase(Locale.ROOT);
        return Arrays.stream(values()).filter(k -> k.id.equals(wanted)).findFirst();
    }

    /**
     * The kind a parameter file describes, from its robot class (ARIA's {@code Class}): a file of class
     * {@code Scout} describes a Scout; any other class, a Pioneer-like robot.
     *
     * @param robotClass the parameter file's robot class
     * @return the kind
     */
    public static RobotKind ofRobotClass(String robotClass) {
        return SCOUT.id.equalsIgnoreCase(robotClass) ? SCOUT : PIONEER;
    }
}
