package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

/**
 * A request of a robot: ARIA's direct motion commands, and switching its sensors. Units: mm, mm/s,
 * degrees, deg/s.
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "cmd")
@JsonSubTypes({
        @JsonSubTypes.Type(value = Command.SetVel.class, name = "vel"),
        @JsonSubTypes.Type(value = Command.SetRotVel.class, name = "rotVel"),
        @JsonSubTypes.Type(value = Command.SetVel2.class, name = "vel2"),
        @JsonSubTypes.Type(value = Command.Move.class, name = "move"),
        @JsonSubTypes.Type(value = Command.SetHeading.class, name = "heading"),
        @JsonSubTypes.Type(value = Command.SetDeltaHeading.class, name = "deltaHeading"),
        @JsonSubTypes.Type(value = Command.Stop.class, name = "stop"),
        @JsonSubTypes.Type(value = Command.SetMaxTransVel.class, name = "maxVel"),
        @JsonSubTypes.Type(value = Command.SetMaxRotVel.class, name = "maxRotVel"),
        @JsonSubTypes.Type(value = Command.SetSonar.class, name = "sonar"),
        @JsonSubTypes.Type(value = Command.ConfigureLaser.class, name = "laser"),
        @JsonSubTypes.Type(value = Command.ConfigureHeatSensor.class, name = "heatSensor"),
        @JsonSubTypes.Type(value = Command.SendMessage.class, name = "send"),
        @JsonSubTypes.Type(value = Command.JoinGroup.class, name = "join"),
        @JsonSubTypes.Type(value = Command.LeaveGroup.class, name = "leave"),
        @JsonSubTypes.Type(value = Command.ReportFound.class, name = "found"),
        @JsonSubTypes.Type(value = Command.Say.class, name = "say"),
        @JsonSubTypes.Type(value = Command.MoveWheels.class, name = "moveWheels"),
        @JsonSubTypes.Type(value = Command.SetAccel.class, name = "accel"),
})
public sealed interface Command {
    /** @param vel translational velocity, mm/s */
    record SetVel(double vel) implements Command { }

    /** @param rotVel rotational velocity, deg/s, positive counter-clockwise */
    record SetRotVel(double rotVel) implements Command { }

    /**
     * @param left  left wheel velocity, mm/s
     * @param right right wheel velocity, mm/s
     */
    record SetVel2(double left, double right) implements Command { }

    /** @param distance mm to travel from the current pose; negative is backwards */
    record Move(double distance) implements Command { }

    /** @param heading absolute heading to turn to, degrees */
    record SetHeading(double heading) implements Command { }

    /** @param delta degrees to turn from the current heading */
    record SetDeltaHeading(double delta) implements Command { }

    /** Translational and rotational velocity to zero at once. */
    record Stop() implements Command { }

    /** @param vel new translational limit, mm/s, within the parameter file's maximum */
    record SetMaxTransVel(double vel) implements Command { }

    /** @param rotVel new rotational limit, deg/s, within the parameter file's maximum */
    record SetMaxRotVel(double rotVel) implements Command { }

    /** @param on whether the sonars fire (ARIA's {@code enableSonar} / {@code disableSonar}) */
    record SetSonar(boolean on) implements Command { }

    /**
     * Switches the robot's laser (a SICK LMS200 at the parameter file's laser pose) on or off.
     *
     * @param on        whether it scans
     * @param increment degrees between readings over its 180° field: 1 (181 readings) or 0.5 (361)
     * @param maxRange  its maximum range, mm
     */
    record ConfigureLaser(boolean on, double increment, double maxRange) implements Command { }

    /**
     * Switches the robot's heat sensor on or off.
     *
     * @param on          whether it senses
     * @param fieldOfView its field of view, degrees, centred on the robot's heading
     * @param maxRange    the farthest source it senses, mm
     */
    record ConfigureHeatSensor(boolean on, double fieldOfView, double maxRange) implements Command { }

    /** How a message is addressed. */
    enum Addressing {
        /** To one robot, by name. */
        ROBOT,
        /** To the members of a group. */
        GROUP,
        /** To every other robot. */
        ALL
    }

    /**
     * Sends a message through the Environment's CommunicationsSystem.
     *
     * @param id   the sender's number for it, named in any error about it
     * @param mode how it is addressed
     * @param to   the robot or group; ignored for {@link Addressing#ALL}
     * @param kind {@code text}, or the name of the type the JSON body encodes
     * @param body the payload
     */
    record SendMessage(long id, Addressing mode, String to, String kind, String body) implements Command { }

    /** @param group a group to join: multicasts to it reach this robot */
    record JoinGroup(String group) implements Command { }

    /** @param group a group to leave */
    record LeaveGroup(String group) implements Command { }

    /**
     * The robot reports that it has found an object of the world, for the Environment to check
     * against the object's true position (GoldFinder's gold).
     *
     * @param object what was found, for example {@code gold}
     */
    record ReportFound(String object) implements Command { }

    /** @param text text the robot says: shown by viewers, kept in recordings and the log */
    record Say(String text) implements Command { }

    /**
     * Moves each wheel by a distance (the Nomad's {@code pr}): both wheels start and finish together.
     *
     * @param left  mm for the left wheel, negative backwards
     * @param right mm for the right wheel
     */
    record MoveWheels(double left, double right) implements Command { }

    /**
     * Sets the accelerations, within nothing but being positive (the Nomad's {@code ac}).
     *
     * @param trans translational acceleration and deceleration, mm/s²
     * @param rot   rotational acceleration and deceleration, deg/s²
     */
    record SetAccel(double trans, double rot) implements Command { }
}
