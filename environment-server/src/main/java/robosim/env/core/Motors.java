package robosim.env.core;

import robosim.protocol.Command;

/**
 * A robot's motor switch, as a Pioneer's firmware keeps it (ARIA's ArRobot.cpp sends ENABLE 1 and 0;
 * the SIP's flags say whether the motors are on, see docs/ARIA-SEMANTICS.md): while the motors are
 * disabled the velocity, move, heading and wheel commands are ignored, and the robot is told so
 * once for each disabled spell. The limits and accelerations still take effect, and a stop is
 * always obeyed. A robot without a switch (a Scout) has its motors always on.
 */
final class Motors {
    private final boolean switchable;
    private boolean enabled;
    private boolean told;

    /**
     * @param switchable whether the robot has a motor switch (a Pioneer has; a Scout has not)
     * @param enabled    whether its motors are enabled at the start (ignored without a switch)
     */
    Motors(boolean switchable, boolean enabled) {
        this.switchable = switchable;
        this.enabled = enabled || !switchable;
    }

    /** @return whether the motors are enabled */
    boolean enabled() {
        return enabled;
    }

    /**
     * Switches the motors.
     *
     * @param on whether to enable them
     * @return whether they were on and are now off: the robot must stop
     */
    boolean set(boolean on) {
        if (!switchable) {
            return false;
        }
        boolean stops = enabled && !on;
        if (on != enabled) {
            told = false;
        }
        enabled = on;
        return stops;
    }

    /**
     * @param c a motion command
     * @return null if the drive takes it; otherwise why it is ignored, the first time in this
     *         disabled spell, or "" after that
     */
    String refusal(Command.Motion c) {
        if (enabled || !moves(c)) {
            return null;
        }
        if (told) {
            return "";
        }
        told = true;
        return "motors are disabled: call enableMotors() first; " + ariaName(c)
                + " ignored (said once until the motors are enabled)";
    }

    /** Whether a command sets the robot going: the velocities, moves, headings and wheel commands. */
    private static boolean moves(Command.Motion c) {
        return c instanceof Command.SetVel || c instanceof Command.SetRotVel || c instanceof Command.SetVel2
                || c instanceof Command.Move || c instanceof Command.SetHeading
                || c instanceof Command.SetDeltaHeading || c instanceof Command.MoveWheels;
    }

    /** The ARIA call that sends a command, for the robot's programmer. */
    private static String ariaName(Command.Motion c) {
        String simple = c.getClass().getSimpleName();
        return Character.toLowerCase(simple.charAt(0)) + simple.substring(1);
    }
}
