package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.List;

/**
 * What a robot learns about itself at the start of a step: the responses to its requests of the
 * previous step.
 *
 * @param step       the step these values are the result of (0 before the first step)
 * @param timeMs     simulated time at the end of that step
 * @param x          odometry x in mm
 * @param y          odometry y in mm
 * @param th         odometry heading in degrees, in (-180, 180]
 * @param vel        translational velocity in mm/s
 * @param rotVel     rotational velocity in deg/s
 * @param leftVel    left wheel velocity in mm/s
 * @param rightVel   right wheel velocity in mm/s
 * @param stalled    whether the last motion was stopped by a collision
 * @param sonar      range in mm of each sonar transducer, by index; empty when the sonars are off
 * @param collisions collisions counted since the start
 * @param laser      the laser's latest scan in mm, from its right (−90°) to its left (+90°); empty
 *                   when the robot has no laser switched on
 * @param heat       the heat sensor's reading, or null when the robot has no heat sensor
 * @param messages   the messages delivered to the robot in that step, in delivery order
 * @param errors     what was wrong with requests of the robot (an unknown recipient, a message over
 *                   the size limit, ...), in the order they were made
 * @param bumpers    the bumper ring's contacts: bit i set when the body touches something in sector i
 *                   of {@value #BUMPER_SECTORS}, sector 0 centred dead ahead, counting counter-clockwise
 * @param truePose   the robot's true pose (x mm, y mm, th degrees) when it asked for it with
 *                   {@link Command.ReportTruePose}; null otherwise
 * @param gripper    the state of the robot's gripper, or null when its parameters give it none
 * @param camera     the pan-tilt-zoom camera's position and ACTS blobs once the robot switched its camera
 *                   on ({@link Command.ConfigurePtz} or {@link Command.TrackColors}); null otherwise
 * @param sonarNew   which sonar readings are new in this state when the ring fires in sequence
 *                   ({@link Command.SetSonarCycle}): bit i set when transducer i fired; null when
 *                   every transducer fired (the ring fires every step, or the sonars are off)
 * @param motorsEnabled whether the robot's motors are enabled (see {@link Command.SetMotors}); null when
 *                   whoever made the state does not know
 */
public record RobotState(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                         double leftVel, double rightVel, boolean stalled, int[] sonar, int collisions,
                         int[] laser, HeatReading heat, List<MessageDelivery> messages, List<String> errors,
                         int bumpers, @JsonInclude(JsonInclude.Include.NON_NULL) double[] truePose,
                         @JsonInclude(JsonInclude.Include.NON_NULL) GripperState gripper,
                         @JsonInclude(JsonInclude.Include.NON_NULL) CameraView camera,
                         @JsonInclude(JsonInclude.Include.NON_NULL) Long sonarNew,
                         @JsonInclude(JsonInclude.Include.NON_NULL) Boolean motorsEnabled) {

    /**
     * @param i a transducer's index
     * @return whether its reading is new in this state ({@link #sonarNew()} null means all are)
     */
    public boolean isSonarNew(int i) {
        return sonarNew == null || i >= 0 && i < Long.SIZE && (sonarNew >> i & 1) != 0;
    }

    /** The bumper ring's sectors, 60° each. */
    public static final int BUMPER_SECTORS = 6;

    /** Copies the lists so the record stays immutable. */
    public RobotState {
        messages = messages == null ? List.of() : List.copyOf(messages);
        errors = errors == null ? List.of() : List.copyOf(errors);
    }

    /**
     * A state with only the motion and the sonar: no laser or heat readings, messages, errors, bumper
     * contacts, true pose, gripper or camera, every sonar reading new, and not saying whether the motors
     * are enabled.
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
     * @param sonar      sonar ranges, mm; empty when the sonars are off
     * @param collisions collisions so far
     */
    public RobotState(long step, long timeMs, double x, double y, double th, double vel, double rotVel,
                      double leftVel, double rightVel, boolean stalled, int[] sonar, int collisions) {
        this(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, sonar, collisions, new int[0], null,
                List.of(), List.of(), 0, null, null, null, null, null);
    }
}
