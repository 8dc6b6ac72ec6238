package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.List;

/**
 * The world's moving parts after one step, sent to every viewer.
 *
 * @param step   the step just completed
 * @param timeMs simulated time after it
 * @param robots   every robot of the world, in the world file's order
 * @param messages the messages robots sent in this step (accepted by the CommunicationsSystem)
 * @param said     what robots said in this step
 * @param events   the robots that joined or went since the snapshot before, in the order they did;
 *                 absent (read as none) in recordings made before robots could join a run under way
 * @param objects  the world's movable objects (pucks) where they are now, in the world file's order;
 *                 absent (read as none) in recordings made before worlds had objects
 * @param drawings the robots' drawings that changed in this step (one with no figures was cleared);
 *                 a viewer that attaches gets every robot's current drawings in its first snapshot.
 *                 Absent (read as none) when none changed, and in recordings made before robots drew
 * @param metrics  the metrics robots reported in this step ({@link Command.ReportMetric}), the last
 *                 value of each robot's name in the step, in the order they were first reported in it;
 *                 absent (read as none) when none was, and in recordings made before robots reported them
 * @param endRequest the robot's request to end the run that ends it after this step
 *                 ({@link Command.EndRun}), in the snapshot of the step it came in; absent (null)
 *                 otherwise, and in recordings made before robots could end a run
 */
public record Snapshot(long step, long timeMs, List<RobotView> robots, List<MessageDelivery> messages,
                          List<Said> said, List<Event> events,
                       @JsonInclude(JsonInclude.Include.NON_EMPTY) List<ObjectView> objects,
                       @JsonInclude(JsonInclude.Include.NON_EMPTY) List<Drawing> drawings,
                       @JsonInclude(JsonInclude.Include.NON_EMPTY) List<Metric> metrics,
                       @JsonInclude(JsonInclude.Include.NON_NULL) EndRequest endRequest) implements Message {
    /** Copies the lists so the record stays immutable. */
    public Snapshot {
        robots = List.copyOf(robots);
        messages = messages == null ? List.of() : List.copyOf(messages);
        said = said == null ? List.of() : List.copyOf(said);
        events = events == null ? List.of() : List.copyOf(events);
        objects = objects == null ? List.of() : List.copyOf(objects);
        drawings = drawings == null ? List.of() : List.copyOf(drawings);
        metrics = metrics == null ? List.of() : List.copyOf(metrics);
    }

    /**
     * A snapshot in which no robot reported a metric or asked to end the run.
     *
     * @param step     the step just completed
     * @param timeMs   simulated time after it
     * @param robots   every robot
     * @param messages the messages robots sent in this step
     * @param said     what robots said in this step
     * @param events   the robots that joined or went since the snapshot before
     * @param objects  the world's objects where they are now
     * @param drawings the robots' drawings that changed in this step
     */
    public Snapshot(long step, long timeMs, List<RobotView> robots, List<MessageDelivery> messages, List<Said> said,
                    List<Event> events, List<ObjectView> objects, List<Drawing> drawings) {
        this(step, timeMs, robots, messages, said, events, objects, drawings, List.of(), null);
    }

    /**
     * A snapshot in which no drawing changed.
     *
     * @param step     the step just completed
     * @param timeMs   simulated time after it
     * @param robots   every robot
     * @param messages the messages robots sent in this step
     * @param said     what robots said in this step
     * @param events   the robots that joined or went since the snapshot before
     * @param objects  the world's objects where they are now
     */
    public Snapshot(long step, long timeMs, List<RobotView> robots, List<MessageDelivery> messages, List<Said> said,
                    List<Event> events, List<ObjectView> objects) {
        this(step, timeMs, robots, messages, said, events, objects, List.of());
    }

    /**
     * @param changed the robots' drawings to carry: those that changed, or for a viewer that
     *                attaches, all there are
     * @return this snapshot with those drawings
     */
    public Snapshot withDrawings(List<Drawing> changed) {
        return new Snapshot(step, timeMs, robots, messages, said, events, objects, changed, metrics, endRequest);
    }

    /**
     * One layer of a robot's drawings, as it is after a step.
     *
     * @param robot   the robot that drew it
     * @param layer   the layer's name
     * @param figures what it shows; empty when the robot cleared it or left
     */
    public record Drawing(String robot, String layer, List<Figure> figures) {
        /**
         * Copies the figures; null reads as none.
         *
         * @throws IllegalArgumentException if the robot is missing, or the layer or its figures break
         *                                  {@link Command.Draw}'s rules
         */
        public Drawing {
            if (robot == null || robot.isEmpty()) {
                throw new IllegalArgumentException("a drawing of layer " + layer + " needs the robot that drew it");
            }
            Command.Draw.requireLayer(layer);
            figures = figures == null ? List.of() : figures;
            Command.Draw.requireFits(layer, figures);
            figures = List.copyOf(figures);
        }
    }

    /**
     * A snapshot in which no robot joined or went.
     *
     * @param step     the step just completed
     * @param timeMs   simulated time after it
     * @param robots   every robot
     * @param messages the messages robots sent in this step
     * @param said     what robots said in this step
     */
    public Snapshot(long step, long timeMs, List<RobotView> robots, List<MessageDelivery> messages, List<Said> said) {
        this(step, timeMs, robots, messages, said, List.of());
    }

    /**
     * @param happened the robots that joined or went since the snapshot before
     * @return this snapshot with those events
     */
    public Snapshot withEvents(List<Event> happened) {
        return new Snapshot(step, timeMs, robots, messages, said, happened, objects, drawings, metrics, endRequest);
    }

    /**
     * @param reported   the metrics robots reported in this step
     * @param endRequest the request to end the run that came in this step, or null
     * @return this snapshot with those run events
     */
    public Snapshot withRunEvents(List<Metric> reported, EndRequest endRequest) {
        return new Snapshot(step, timeMs, robots, messages, said, events, objects, drawings, reported, endRequest);
    }

    /**
     * A metric a robot reported ({@link Command.ReportMetric}), for viewers and recordings.
     *
     * @param robot the robot
     * @param name  the metric's name
     * @param value its value
     */
    public record Metric(String robot, String name, double value) {
        /**
         * @throws IllegalArgumentException if the robot is missing, or the name or the value breaks
         *                                  {@link Command.ReportMetric}'s rules
         */
        public Metric {
            if (robot == null || robot.isEmpty()) {
                throw new IllegalArgumentException("metric " + name + " needs the robot that reported it");
            }
            Command.ReportMetric.requireName(name);
            Command.ReportMetric.requireValue(name, value);
        }
    }

    /**
     * A robot's request to end the run ({@link Command.EndRun}), the first of the run, which ended it.
     *
     * @param robot  the robot
     * @param step   the step it came in; the run ended after it
     * @param reason why, as the robot said it
     */
    public record EndRequest(String robot, long step, String reason) {
        /**
         * @throws IllegalArgumentException if the robot is missing, the step is below 1, or the reason
         *                                  breaks {@link Command.EndRun}'s rule
         */
        public EndRequest {
            if (robot == null || robot.isEmpty()) {
                throw new IllegalArgumentException("a request to end the run needs the robot that made it");
            }
            if (step < 1) {
                throw new IllegalArgumentException(step + " was supplied for the step of robot " + robot
                        + "'s request to end the run: steps count from 1");
            }
            Command.EndRun.requireReason(reason);
        }
    }

    /**
     * A robot that joined the run under way or went from it, for viewers and recordings.
     *
     * @param robot  the robot
     * @param what   {@code joined late}, {@code rejoined}, {@code spawned}, {@code left},
     *               {@code dropped} or {@code lost}
     * @param step   for a join the first step it takes part in; for a departure the step open when
     *               it went (or the last step run)
     * @param reason why it went (its bye's reason, the rule it broke); empty for a join
     */
    public record Event(String robot, String what, long step, String reason) { }

    /**
     * A snapshot without messages or speech.
     *
     * @param step   the step just completed
     * @param timeMs simulated time after it
     * @param robots every robot
     */
    public Snapshot(long step, long timeMs, List<RobotView> robots) {
        this(step, timeMs, robots, List.of(), List.of());
    }

    /**
     * Text a robot said (ARIA's {@code SAY}, the Scout's {@code tk}), for viewers and logs.
     *
     * @param robot the robot
     * @param text  what it said
     */
    public record Said(String robot, String text) { }

    /**
     * One robot's true pose and status.
     *
     * @param name      the robot's name
     * @param x         true x in mm
     * @param y         true y in mm
     * @param th        true heading in degrees
     * @param stalled   whether it is stalled against something
     * @param connected whether its program is connected
     * @param sonar     its sonar ranges in mm, by index
     * @param odoX      odometry x, mm: where the robot believes it is
     * @param odoY      odometry y, mm
     * @param odoTh     odometry heading, degrees
     * @param laser     its latest laser scan, mm, right to left; empty when off
     * @param laserIncrement degrees between laser readings (1 or 0.5)
     * @param vel       translational velocity, mm/s
     * @param rotVel    rotational velocity, deg/s
     * @param camera    its pan-tilt-zoom camera while on: {pan, horizontal field of view}, degrees
     *                  (pan positive to the right, as ARIA's); null while off
     */
    public record RobotView(String name, double x, double y, double th, boolean stalled,
                            boolean connected, int[] sonar, double odoX, double odoY, double odoTh,
                            int[] laser, double laserIncrement, double vel, double rotVel,
                            @com.fasterxml.jackson.annotation.JsonInclude(
                                    com.fasterxml.jackson.annotation.JsonInclude.Include.NON_NULL) double[] camera) {

        /**
         * A view without a camera.
         *
         * @param name           the robot's name
         * @param x              true x, mm
         * @param y              true y, mm
         * @param th             true heading, degrees
         * @param stalled        whether stalled
         * @param connected      whether connected
         * @param sonar          sonar ranges, mm
         * @param odoX           odometry x, mm
         * @param odoY           odometry y, mm
         * @param odoTh          odometry heading, degrees
         * @param laser          laser scan, mm
         * @param laserIncrement degrees between laser readings
         * @param vel            mm/s
         * @param rotVel         deg/s
         */
        public RobotView(String name, double x, double y, double th, boolean stalled, boolean connected, int[] sonar,
                         double odoX, double odoY, double odoTh, int[] laser, double laserIncrement, double vel,
                         double rotVel) {
            this(name, x, y, th, stalled, connected, sonar, odoX, odoY, odoTh, laser, laserIncrement, vel, rotVel,
                    null);
        }

        /**
         * A view without velocities.
         *
         * @param name           the robot's name
         * @param x              true x, mm
         * @param y              true y, mm
         * @param th             true heading, degrees
         * @param stalled        whether stalled
         * @param connected      whether connected
         * @param sonar          sonar ranges, mm
         * @param odoX           odometry x, mm
         * @param odoY           odometry y, mm
         * @param odoTh          odometry heading, degrees
         * @param laser          laser scan, mm
         * @param laserIncrement degrees between laser readings
         */
        public RobotView(String name, double x, double y, double th, boolean stalled, boolean connected, int[] sonar,
                         double odoX, double odoY, double odoTh, int[] laser, double laserIncrement) {
            this(name, x, y, th, stalled, connected, sonar, odoX, odoY, odoTh, laser, laserIncrement, 0, 0);
        }

        /**
         * A view whose odometry is the true pose and without a laser.
         *
         * @param name      the robot's name
         * @param x         true x, mm
         * @param y         true y, mm
         * @param th        true heading, degrees
         * @param stalled   whether stalled
         * @param connected whether connected
         * @param sonar     sonar ranges, mm
         */
        public RobotView(String name, double x, double y, double th, boolean stalled, boolean connected, int[] sonar) {
            this(name, x, y, th, stalled, connected, sonar, x, y, th, new int[0], 1, 0, 0);
        }
    }

    /**
     * A snapshot without world objects.
     *
     * @param step     the step just completed
     * @param timeMs   simulated time after it
     * @param robots   every robot
     * @param messages the messages robots sent in this step
     * @param said     what robots said in this step
     * @param events   the robots that joined or went since the snapshot before
     */
    public Snapshot(long step, long timeMs, List<RobotView> robots, List<MessageDelivery> messages, List<Said> said,
                    List<Event> events) {
        this(step, timeMs, robots, messages, said, events, List.of());
    }

    /**
     * @param others the world's objects where they are now
     * @return this snapshot with those objects
     */
    public Snapshot withObjects(List<ObjectView> others) {
        return new Snapshot(step, timeMs, robots, messages, said, events, others, drawings, metrics, endRequest);
    }

    /**
     * A movable world object (a puck) where it is now.
     *
     * @param x      its centre, mm
     * @param y      its centre, mm
     * @param heldBy the robot whose gripper holds it, or null when it lies on the floor
     * @param lifted whether it is held off the floor (the holder's lift is not at the bottom)
     */
    public record ObjectView(double x, double y, String heldBy, boolean lifted) { }
}
