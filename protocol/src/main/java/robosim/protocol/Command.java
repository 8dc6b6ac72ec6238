package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;
import java.util.List;
import java.util.Locale;

/**
 * A request of a robot: ARIA's direct motion commands, switching its sensors, messages to other
 * robots, and events of the run. Units: mm, mm/s, degrees, deg/s.
 *
 * <p>Each command belongs to one group, named after what carries it out in the Environment:
 * {@link Motion}, {@link SensorSetting}, {@link Messaging}, {@link RunEvent}, {@link Simulator} and {@link Accessory}. Each record checks
 * its values as it is made, so a command that breaks a rule (a non-finite velocity, a laser
 * increment no SICK has) cannot exist, on the robot's side or decoded from the wire.
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
        @JsonSubTypes.Type(value = Command.SetDriveLimit.class, name = "driveLimit"),
        @JsonSubTypes.Type(value = Command.SetTruePose.class, name = "truePose"),
        @JsonSubTypes.Type(value = Command.ResetToStart.class, name = "resetToStart"),
        @JsonSubTypes.Type(value = Command.ReportTruePose.class, name = "reportTruePose"),
        @JsonSubTypes.Type(value = Command.Gripper.class, name = "gripper"),
        @JsonSubTypes.Type(value = Command.ConfigurePtz.class, name = "ptz"),
        @JsonSubTypes.Type(value = Command.AimPtz.class, name = "aimPtz"),
        @JsonSubTypes.Type(value = Command.TrackColors.class, name = "trackColors"),
        @JsonSubTypes.Type(value = Command.BindChannel.class, name = "bindChannel"),
        @JsonSubTypes.Type(value = Command.SetSonarCycle.class, name = "sonarCycle"),
        @JsonSubTypes.Type(value = Command.SetMotors.class, name = "motors"),
        @JsonSubTypes.Type(value = Command.Draw.class, name = "draw"),
        @JsonSubTypes.Type(value = Command.ReportMetric.class, name = "metric"),
        @JsonSubTypes.Type(value = Command.EndRun.class, name = "endRun"),
})
public sealed interface Command {
    /** Commands carried out by the robot's drive controller. */
    sealed interface Motion extends Command { }

    /** Commands that switch or configure the robot's sensors. */
    sealed interface SensorSetting extends Command { }

    /** Commands carried out by the Environment's CommunicationsSystem. */
    sealed interface Messaging extends Command { }

    /** Events of the run, kept in the run's log, recordings and viewers. */
    sealed interface RunEvent extends Command { }

    /**
     * Operations of the simulator on the robot itself, as MobileSim's SIM_SET_POSE and SIM_RESET:
     * carried out by the Environment's simulation, refused with a reason when they cannot be.
     */
    sealed interface Simulator extends Command { }

    /**
     * Its constructor throws IllegalArgumentException if it is not finite.
     *
     * @param vel translational velocity, mm/s
     */
    record SetVel(double vel) implements Motion {
        public SetVel {
            finite("vel", vel);
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is not finite.
     *
     * @param rotVel rotational velocity, deg/s, positive counter-clockwise
     */
    record SetRotVel(double rotVel) implements Motion {
        public SetRotVel {
            finite("rotVel", rotVel);
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if either is not finite.
     *
     * @param left  left wheel velocity, mm/s
     * @param right right wheel velocity, mm/s
     */
    record SetVel2(double left, double right) implements Motion {
        public SetVel2 {
            finite("left", left);
            finite("right", right);
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is not finite.
     *
     * @param distance mm to travel from the current pose; negative is backwards
     */
    record Move(double distance) implements Motion {
        public Move {
            finite("distance", distance);
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is not finite.
     *
     * @param heading absolute heading to turn to, degrees
     */
    record SetHeading(double heading) implements Motion {
        public SetHeading {
            finite("heading", heading);
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is not finite.
     *
     * @param delta degrees to turn from the current heading
     */
    record SetDeltaHeading(double delta) implements Motion {
        public SetDeltaHeading {
            finite("delta", delta);
        }
    }

    /** Translational and rotational velocity to zero at once. */
    record Stop() implements Motion { }

    /**
     * Its constructor throws IllegalArgumentException if it is not finite.
     *
     * @param vel new translational limit, mm/s, within the parameter file's maximum
     */
    record SetMaxTransVel(double vel) implements Motion {
        public SetMaxTransVel {
            finite("maxVel", vel);
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is not finite.
     *
     * @param rotVel new rotational limit, deg/s, within the parameter file's maximum
     */
    record SetMaxRotVel(double rotVel) implements Motion {
        public SetMaxRotVel {
            finite("maxRotVel", rotVel);
        }
    }

    /** @param on whether the sonars fire (ARIA's {@code enableSonar} / {@code disableSonar}) */
    record SetSonar(boolean on) implements SensorSetting { }

    /**
     * Switches the robot's laser (a SICK LMS200 at the parameter file's laser pose) on or off.
     *
     * Its constructor throws IllegalArgumentException if the increment is neither, or the range is not
     * a finite number greater than 0.
     *
     * @param on        whether it scans
     * @param increment degrees between readings over its 180° field: 1 (181 readings) or 0.5 (361)
     * @param maxRange  its maximum range, mm
     */
    record ConfigureLaser(boolean on, double increment, double maxRange) implements SensorSetting {
        public ConfigureLaser {
            requireIncrement("the laser increment", increment);
            positive("laser maxRange", maxRange);
        }

        /**
         * The increments a SICK LMS200 has, as one rule for every place that takes one.
         *
         * @param name      what the value is called where it was given
         * @param increment degrees between readings
         * @throws IllegalArgumentException if it is neither 1 nor 0.5
         */
        public static void requireIncrement(String name, double increment) {
            if (increment != 1 && increment != 0.5) {
                throw new IllegalArgumentException(increment + " was supplied for " + name
                        + ": a SICK LMS200 scans at 1 or 0.5 degrees");
            }
        }
    }

    /**
     * Switches the robot's heat sensor on or off.
     *
     * Its constructor throws IllegalArgumentException if the field of view is not above 0 and at most
     * 360, or the range is not a finite number greater than 0.
     *
     * @param on          whether it senses
     * @param fieldOfView its field of view, degrees, centred on the robot's heading
     * @param maxRange    the farthest source it senses, mm
     */
    record ConfigureHeatSensor(boolean on, double fieldOfView, double maxRange) implements SensorSetting {
        public ConfigureHeatSensor {
            positive("heat fieldOfView", fieldOfView);
            positive("heat maxRange", maxRange);
            if (fieldOfView > 360) {
                throw new IllegalArgumentException(fieldOfView
                        + " was supplied for heat fieldOfView: at most 360 degrees");
            }
        }
    }

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
     * Its constructor throws IllegalArgumentException if the mode, kind or body is missing, or a
     * message to a robot or a group names none.
     *
     * @param id   the sender's number for it, named in any error about it
     * @param mode how it is addressed
     * @param to   the robot or group; ignored for {@link Addressing#ALL}
     * @param kind {@code text}, or the name of the type the JSON body encodes
     * @param body the payload
     */
    record SendMessage(long id, Addressing mode, String to, String kind, String body) implements Messaging {
        public SendMessage {
            if (mode == null || kind == null || body == null) {
                throw new IllegalArgumentException("message " + id + " needs a mode, a kind and a body");
            }
            if (mode != Addressing.ALL && (to == null || to.isBlank())) {
                throw new IllegalArgumentException("message " + id + " is addressed to a "
                        + mode.name().toLowerCase() + " but names none");
            }
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is missing or blank.
     *
     * @param group a group to join: multicasts to it reach this robot
     */
    record JoinGroup(String group) implements Messaging {
        public JoinGroup {
            named(group, "a group to join needs a name");
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is missing or blank.
     *
     * @param group a group to leave
     */
    record LeaveGroup(String group) implements Messaging {
        public LeaveGroup {
            named(group, "a group to leave needs a name");
        }
    }

    /**
     * The robot reports that it has found an object of the world, for the Environment to check
     * against the object's true position (GoldFinder's gold).
     *
     * Its constructor throws IllegalArgumentException if it is missing or blank.
     *
     * @param object what was found, for example {@code gold}
     */
    record ReportFound(String object) implements RunEvent {
        public ReportFound {
            named(object, "a report of a find needs the object's name");
        }
    }

    /**
     * Its constructor throws IllegalArgumentException if it is missing or longer than 1000 characters.
     *
     * @param text text the robot says: shown by viewers, kept in recordings and the log
     */
    record Say(String text) implements RunEvent {
        public Say {
            if (text == null || text.length() > 1000) {
                throw new IllegalArgumentException("a robot says at most 1000 characters, not "
                        + (text == null ? "nothing" : text.length()));
            }
        }
    }

    /**
     * Reports one of the robot's figures for the run's results, such as the cells it explored: the
     * Environment keeps the last value of each name for the run's report, and its recordings and
     * viewers see each report. It keeps at most {@value #MAX_METRICS} names per robot and refuses a
     * new name past them with an error the robot reads next.
     *
     * Its constructor throws IllegalArgumentException if the name is not a letter followed by up to
     * 63 letters, digits, {@code _}, {@code .} or {@code -}, or the value is not finite.
     *
     * @param name  what the figure is called, such as {@code cellsExplored}
     * @param value its value now
     */
    record ReportMetric(String name, double value) implements RunEvent {
        /** The most names one robot may report in a run. */
        public static final int MAX_METRICS = 64;
        /** The most characters in a name. */
        public static final int MAX_NAME = 64;

        public ReportMetric {
            requireName(name);
            requireValue(name, value);
        }

        /**
         * The rule for a metric's name, as one rule for every place that takes one.
         *
         * @param name the name
         * @throws IllegalArgumentException if it is not a letter followed by up to 63 letters,
         *                                  digits, {@code _}, {@code .} or {@code -}
         */
        public static void requireName(String name) {
            if (name == null || !name.matches("[A-Za-z][A-Za-z0-9_.-]{0," + (MAX_NAME - 1) + "}")) {
                String what = name == null ? "null" : name.length() > MAX_NAME
                        ? "a name of " + name.length() + " characters" : "'" + name + "'";
                throw new IllegalArgumentException(what + " was supplied for a metric's name: a letter, then up to "
                        + (MAX_NAME - 1) + " letters, digits, '_', '.' or '-'");
            }
        }

        /**
         * The rule for a metric's value, as one rule for every place that takes one.
         *
         * @param name  the metric's name, for the message
         * @param value its value
         * @throws IllegalArgumentException if it is not finite
         */
        public static void requireValue(String name, double value) {
            finite("metric " + name, value);
        }
    }

    /**
     * Asks the Environment to end the run after this step, as a program does that has found what it
     * looked for. The first request of a run counts: the run ends after the step it came in, its
     * report names the robot, the step and the reason; later requests change nothing.
     *
     * Its constructor throws IllegalArgumentException if the reason is not 1 to
     * {@value #MAX_REASON} characters, or holds a control character (a line break, a tab, ...).
     *
     * @param reason why, for the run's report and log, such as {@code gold found}
     */
    record EndRun(String reason) implements RunEvent {
        /** The most characters in a reason. */
        public static final int MAX_REASON = 200;

        public EndRun {
            requireReason(reason);
        }

        /**
         * The rule for the reason of an end request, as one rule for every place that takes one.
         *
         * @param reason the reason
         * @throws IllegalArgumentException if it is not 1 to {@value #MAX_REASON} characters, or
         *                                  holds a control character
         */
        public static void requireReason(String reason) {
            if (reason == null || reason.isEmpty() || reason.length() > MAX_REASON) {
                throw new IllegalArgumentException((reason == null ? "null" : "a reason of " + reason.length()
                        + " characters") + " was supplied for ending the run: 1 to " + MAX_REASON + " characters");
            }
            for (int i = 0; i < reason.length(); i++) {
                char c = reason.charAt(i);
                if (Character.isISOControl(c)) {
                    throw new IllegalArgumentException(String.format(Locale.ROOT, "a reason with the control"
                            + " character U+%04X at index %d was supplied for ending the run: it is one line of text",
                            (int) c, i));
                }
            }
        }
    }

    /**
     * Replaces one layer of the robot's drawings, the shapes it shows in the world's views (its known
     * map, the frontier it claimed): viewers draw the figures until the robot replaces the layer,
     * clears it with an empty list, or leaves. The Environment keeps at most
     * {@value #MAX_LAYERS} layers per robot, and a bounded number of coordinates in all the robots'
     * layers together, and refuses a layer past either with the reason.
     *
     * Its constructor throws IllegalArgumentException if the layer is not 1 to 32 letters, digits,
     * dots, underscores or hyphens, the figures are missing or null, or there are more than
     * {@value #MAX_FIGURES} figures or {@value Figure#MAX_NUMBERS} numbers in all.
     *
     * @param layer   the layer's name, such as {@code map} or {@code frontier}
     * @param figures what the layer shows now; empty clears it
     */
    record Draw(String layer, List<Figure> figures) implements RunEvent {
        /** The most layers one robot may have at once. */
        public static final int MAX_LAYERS = 8;
        /** The most figures in one drawing. */
        public static final int MAX_FIGURES = 256;

        public Draw {
            requireLayer(layer);
            if (figures == null) {
                throw new IllegalArgumentException("layer " + layer + " needs its figures: an empty list clears it");
            }
            requireFits(layer, figures);
            figures = List.copyOf(figures);
        }

        /**
         * The caps on one layer's figures, as one rule for every place that takes them.
         *
         * @param layer   the layer's name, for the message
         * @param figures its figures
         * @throws IllegalArgumentException if one is null, or there are more than {@value #MAX_FIGURES}
         *                                  figures or {@value Figure#MAX_NUMBERS} numbers in all
         */
        public static void requireFits(String layer, List<Figure> figures) {
            if (figures.size() > MAX_FIGURES) {
                throw new IllegalArgumentException(figures.size() + " figures were supplied for layer " + layer
                        + ": at most " + MAX_FIGURES);
            }
            long numbers = 0;
            for (Figure f : figures) {
                if (f == null) {
                    throw new IllegalArgumentException("a null figure was supplied for layer " + layer);
                }
                numbers += f.size();
            }
            if (numbers > Figure.MAX_NUMBERS) {
                throw new IllegalArgumentException(numbers + " numbers were supplied for layer " + layer
                        + ": at most " + Figure.MAX_NUMBERS + " in all its figures");
            }
        }

        /**
         * The rule for a layer's name, as one rule for every place that takes one.
         *
         * @param layer the name
         * @throws IllegalArgumentException if it is not 1 to 32 letters, digits, dots, underscores or hyphens
         */
        public static void requireLayer(String layer) {
            if (layer == null || !layer.matches("[A-Za-z0-9._-]{1,32}")) {
                throw new IllegalArgumentException((layer == null ? "null" : "'" + layer + "'")
                        + " was supplied for a drawing's layer: 1 to 32 letters, digits, '.', '_' or '-'");
            }
        }
    }

    /**
     * Moves each wheel by a distance (the Nomad's {@code pr}): both wheels start and finish together.
     *
     * Its constructor throws IllegalArgumentException if either is not finite.
     *
     * @param left  mm for the left wheel, negative backwards
     * @param right mm for the right wheel
     */
    record MoveWheels(double left, double right) implements Motion {
        public MoveWheels {
            finite("left", left);
            finite("right", right);
        }
    }

    /**
     * Sets the accelerations, within nothing but being positive (the Nomad's {@code ac}).
     *
     * Its constructor throws IllegalArgumentException if either is not a finite number greater than 0.
     *
     * @param trans translational acceleration and deceleration, mm/s²
     * @param rot   rotational acceleration and deceleration, deg/s²
     */
    record SetAccel(double trans, double rot) implements Motion {
        public SetAccel {
            positive("trans accel", trans);
            positive("rot accel", rot);
        }
    }

    /** Which of the drive's acceleration limits a {@link SetDriveLimit} sets. */
    enum DriveLimit {
        /** Translational acceleration, mm/s². */
        TRANS_ACCEL,
        /** Translational deceleration, mm/s². */
        TRANS_DECEL,
        /** Rotational acceleration, deg/s². */
        ROT_ACCEL,
        /** Rotational deceleration, deg/s². */
        ROT_DECEL
    }

    /**
     * Sets one acceleration limit, as ARIA's {@code setTransAccel} and the Pioneer's SETA and SETRA do.
     *
     * Its constructor throws IllegalArgumentException if the limit is null or the value is not a
     * finite number greater than 0.
     *
     * @param limit which limit
     * @param value mm/s² or deg/s²
     */
    record SetDriveLimit(DriveLimit limit, double value) implements Motion {
        public SetDriveLimit {
            named(limit == null ? null : limit.name(), "a drive limit needs its kind");
            positive(limit.name(), value);
        }
    }

    /**
     * Puts the robot at a true pose in the world without touching its odometry (MobileSim's
     * SIM_SET_POSE). Refused when the body would overlap something there.
     *
     * Its constructor throws IllegalArgumentException if a value is not finite.
     *
     * @param x  mm, world frame
     * @param y  mm, world frame
     * @param th degrees
     */
    record SetTruePose(double x, double y, double th) implements Simulator {
        public SetTruePose {
            finite("x", x);
            finite("y", y);
            finite("th", th);
        }
    }

    /** Puts the robot back at its start pose, stopped, with its odometry as at the start (MobileSim's SIM_RESET). */
    record ResetToStart() implements Simulator { }

    /**
     * Switches the ground-truth sensor: while on, each state carries the robot's true pose (what a
     * simulator's SIMSTAT reports).
     *
     * @param on whether to report it
     */
    record ReportTruePose(boolean on) implements SensorSetting { }

    /** Commands carried out by the robot's accessories in the Environment: its gripper. */
    sealed interface Accessory extends Command { }

    /**
     * An operation of the robot's Pioneer gripper, with ARIA's GRIPPER command codes
     * ({@code ArGripperCommands} in ARIA's ArGripper.h): 1 GRIP_OPEN, 2 GRIP_CLOSE, 3 GRIP_STOP,
     * 4 LIFT_UP, 5 LIFT_DOWN, 6 LIFT_STOP, 7 GRIPPER_STORE, 8 GRIPPER_DEPLOY, 15 GRIPPER_HALT,
     * 16 GRIP_PRESSURE and 17 LIFT_CARRY (those two take the GRIPPERVAL argument). Carried out by
     * the Environment's model of the gripper; a robot without a gripper gets an error back.
     *
     * Its constructor throws IllegalArgumentException if the code is none of those.
     *
     * @param op    the GRIPPER command code
     * @param value the GRIPPERVAL argument in 20 ms units (GRIP_PRESSURE: grasp time, 0 to 255;
     *              LIFT_CARRY: lift travel, positive up), 0 for the others
     */
    record Gripper(int op, int value) implements Accessory {
        /** ARIA's GRIP_OPEN. */
        public static final int GRIP_OPEN = 1;
        /** ARIA's GRIP_CLOSE. */
        public static final int GRIP_CLOSE = 2;
        /** ARIA's GRIP_STOP. */
        public static final int GRIP_STOP = 3;
        /** ARIA's LIFT_UP. */
        public static final int LIFT_UP = 4;
        /** ARIA's LIFT_DOWN. */
        public static final int LIFT_DOWN = 5;
        /** ARIA's LIFT_STOP. */
        public static final int LIFT_STOP = 6;
        /** ARIA's GRIPPER_STORE: close the paddles and raise the lift. */
        public static final int GRIPPER_STORE = 7;
        /** ARIA's GRIPPER_DEPLOY: open the paddles and lower the lift. */
        public static final int GRIPPER_DEPLOY = 8;
        /** ARIA's GRIPPER_HALT: stop the paddles and the lift. */
        public static final int GRIPPER_HALT = 15;
        /** ARIA's GRIP_PRESSURE: the grasp time, in 20 ms units. */
        public static final int GRIP_PRESSURE = 16;
        /** ARIA's LIFT_CARRY: move the lift for a time, in 20 ms units, positive up. */
        public static final int LIFT_CARRY = 17;

        public Gripper {
            if (!(op >= GRIP_OPEN && op <= GRIPPER_DEPLOY) && op != GRIPPER_HALT && op != GRIP_PRESSURE
                    && op != LIFT_CARRY) {
                throw new IllegalArgumentException(op + " was supplied for the gripper command: ARIA's codes are "
                        + "1 to 8, 15, 16 and 17");
            }
            if (op == GRIP_PRESSURE && (value < 0 || value > 255)) {
                throw new IllegalArgumentException(value + " was supplied for the grasp time: 0 to 255 (20 ms units)");
            }
            if (op == LIFT_CARRY && (value < Short.MIN_VALUE || value > Short.MAX_VALUE)) {
                throw new IllegalArgumentException(value + " was supplied for the lift carry: a signed 16-bit value");
            }
        }

        /**
         * @param op the GRIPPER command code of an operation without an argument
         */
        public Gripper(int op) {
            this(op, 0);
        }
    }

    /**
     * Switches on the robot's pan-tilt-zoom camera (ARIA's {@code ArPTZ::init}): it starts at pan 0,
     * tilt 0 and its widest zoom, at the robot's centre and this height.
     *
     * Its constructor throws IllegalArgumentException if the model is missing or the height is not
     * a finite number greater than 0.
     *
     * @param model       the camera, which gives its limits, field of view and speed
     * @param mountHeight the lens's height above the floor, mm
     */
    record ConfigurePtz(PtzModel model, double mountHeight) implements SensorSetting {
        public ConfigurePtz {
            named(model == null ? null : model.name(), "a camera needs its model");
            positive("camera mountHeight", mountHeight);
        }
    }

    /**
     * Points the camera (ARIA's {@code panTilt} and {@code zoom}): it moves there at its own speed,
     * the values clamped into its limits as ARIA clamps them.
     *
     * Its constructor throws IllegalArgumentException if pan or tilt is not finite.
     *
     * @param pan  degrees, positive to the right (ARIA's ArPTZ.h: "- is to the left, + to the right")
     * @param tilt degrees, positive up
     * @param zoom the camera's zoom units
     */
    record AimPtz(double pan, double tilt, int zoom) implements SensorSetting {
        public AimPtz {
            finite("pan", pan);
            finite("tilt", tilt);
        }
    }

    /**
     * Starts or stops ACTS's colour tracking on the camera's image (ARIA's
     * {@code ArACTS_1_2::openPort} and {@code closePort}). A robot that has not switched its
     * pan-tilt-zoom camera on tracks through a VC-C4 at its defaults, pointing straight ahead.
     *
     * @param on whether the blobs are computed and reported each step
     */
    record TrackColors(boolean on) implements SensorSetting { }

    /**
     * Binds an ACTS channel to a colour, or frees it: a pixel belongs to the channel when its colour
     * is the channel's.
     *
     * Its constructor throws IllegalArgumentException if the channel is not from 1 to
     * {@value CameraView#CHANNELS} or the colour is neither a name of {@link Colors} nor {@code #rrggbb}.
     *
     * @param channel 1 to {@value CameraView#CHANNELS}
     * @param color   a colour's name or {@code #rrggbb}; null frees the channel
     */
    record BindChannel(int channel, String color) implements SensorSetting {
        public BindChannel {
            if (channel < 1 || channel > CameraView.CHANNELS) {
                throw new IllegalArgumentException(channel + " was supplied for an ACTS channel: channels are 1 to "
                        + CameraView.CHANNELS);
            }
            if (color != null) {
                color = Colors.format(Colors.parse(color));
            }
        }
    }

    /**
     * Sets how the sonar ring fires: 0, every transducer every step; otherwise one firing every
     * {@code msPerFiring} ms of simulated time, each firing one transducer of each bank of eight in
     * index order, as a Pioneer's firmware sequences its ring (its {@code SonarCycle}).
     *
     * @param msPerFiring simulated ms between firings, 0 to {@value #MAX_SONAR_CYCLE_MS}
     */
    record SetSonarCycle(int msPerFiring) implements SensorSetting {
        /** The longest time between firings, ms. */
        public static final int MAX_SONAR_CYCLE_MS = 10_000;

        /** @throws IllegalArgumentException if out of range */
        public SetSonarCycle {
            if (msPerFiring < 0 || msPerFiring > MAX_SONAR_CYCLE_MS) {
                throw new IllegalArgumentException(msPerFiring + " was supplied for msPerFiring: it is 0 (every step)"
                        + " to " + MAX_SONAR_CYCLE_MS + " ms");
            }
        }
    }

    /**
     * Enables or disables a Pioneer's motors, as ARIA's {@code enableMotors} and {@code disableMotors}
     * send ENABLE 1 and ENABLE 0 (ArRobot.cpp). While they are disabled the velocity, move, heading and
     * wheel commands are ignored (the robot is told once); disabling stops the robot. A Scout's motors
     * are always on: it ignores this command.
     *
     * @param on whether the motors are enabled
     */
    record SetMotors(boolean on) implements Motion { }

    private static void finite(String name, double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(v + " was supplied for " + name + ": it must be a finite number");
        }
    }

    private static void positive(String name, double v) {
        if (!(Double.isFinite(v) && v > 0)) {
            throw new IllegalArgumentException(v + " was supplied for " + name + ": it must be greater than 0");
        }
    }

    private static void named(String name, String rule) {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException(rule);
        }
    }
}
