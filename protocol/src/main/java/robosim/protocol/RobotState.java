package robosim.protocol;

import com.fasterxml.jackson.databind.annotation.JsonDeserialize;
import com.fasterxml.jackson.databind.annotation.JsonSerialize;
import java.util.List;

/**
 * What a robot learns about itself at the start of a step: the responses to its requests of the
 * previous step. Its motion and what became of its requests are fields; what its sensors and
 * accessories read are {@linkplain StateParts parts}, one per sensor, read with {@link #get}.
 *
 * <p>On the wire a state is one object: the fields by name, then each part it holds under the
 * part's name ({@code "sonar"}, {@code "laser"}, {@code "battery"}, ...); see {@link RobotStateJson}.
 *
 * @param step          the step these values are the result of (0 before the first step)
 * @param timeMs        simulated time at the end of that step
 * @param x             odometry x in mm
 * @param y             odometry y in mm
 * @param th            odometry heading in degrees, in (-180, 180]
 * @param vel           translational velocity in mm/s
 * @param rotVel        rotational velocity in deg/s
 * @param leftVel       left wheel velocity in mm/s
 * @param rightVel      right wheel velocity in mm/s
 * @param stalled       whether the last motion was stopped by a collision
 * @param collisions    collisions counted since the start
 * @param messages      the messages delivered to the robot in that step, in delivery order
 * @param errors        what was wrong with requests of the robot (an unknown recipient, a message over
 *                      the size limit, ...), in the order they were made
 * @param motorsEnabled whether the robot's motors are enabled (see {@link Command.SetMotors}); null
 *                      when whoever made the state does not know
 * @param parts         what its sensors and accessories read: the sonar ring, the laser, the bumpers,
 *                      the battery, ... (see {@link StateParts#ALL})
 */
@JsonSerialize(using = RobotStateJson.Writer.class)
@JsonDeserialize(using = RobotStateJson.Reader.class)
public record RobotState(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                         double leftVel, double rightVel, boolean stalled, int collisions,
                         List<MessageDelivery> messages, List<String> errors, Boolean motorsEnabled,
                         StateParts parts) {

    /** Copies the lists so the record stays immutable. */
    public RobotState {
        messages = messages == null ? List.of() : List.copyOf(messages);
        errors = errors == null ? List.of() : List.copyOf(errors);
        parts = parts == null ? StateParts.NONE : parts;
    }

    /**
     * A state with only the motion: no messages or errors, no parts, not saying whether the motors
     * are enabled. Add parts with {@link #with}.
     *
     * @param step       the step
     * @param timeMs     simulated time, ms
     * @param x          odometry x, mm
     * @param y          odometry y, mm
     * @param th         odometry heading, degrees
     * @param vel        mm/s
     * @param rotVel     deg/s
     * @param leftVel    mm/s
     * @param rightVel   mm/s
     * @param stalled    whether stalled
     * @param collisions collisions so far
     */
    public RobotState(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                      double leftVel, double rightVel, boolean stalled, int collisions) {
        this(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, collisions, List.of(), List.of(), null,
                StateParts.NONE);
    }

    /**
     * @param part a part's key, such as {@link SonarReading#PART}
     * @param <T>  its value's type
     * @return the part's value, or the key's {@linkplain StatePart#absent() absent} value when the
     *         state holds none (an empty sonar reading, no heat reading)
     */
    public <T> T get(StatePart<T> part) {
        T v = parts.get(part);
        return v == null ? part.absent() : v;
    }

    /**
     * @param part  a part's key
     * @param value its value; null removes it
     * @param <T>   its value's type
     * @return this state with that part
     */
    public <T> RobotState with(StatePart<T> part, T value) {
        return new RobotState(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, collisions, messages,
                errors, motorsEnabled, parts.with(part, value));
    }

    /**
     * @param delivered the messages delivered
     * @param problems  the errors of requests
     * @return this state with those messages and errors
     */
    public RobotState withMessages(List<MessageDelivery> delivered, List<String> problems) {
        return new RobotState(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, collisions, delivered,
                problems, motorsEnabled, parts);
    }

    /**
     * @param enabled whether the motors are enabled; null when not known
     * @return this state saying so
     */
    public RobotState withMotorsEnabled(Boolean enabled) {
        return new RobotState(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, collisions, messages,
                errors, enabled, parts);
    }
}
