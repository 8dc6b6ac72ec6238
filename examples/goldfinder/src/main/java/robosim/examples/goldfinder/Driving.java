package robosim.examples.goldfinder;

import robosim.aria.ArMath;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;

/**
 * How a Gold robot drives its {@link Track}, in ARIA's velocity calls, a step at a time: it steers
 * for a point a little ahead on the track (pure pursuit), so it takes each bend as an arc without
 * stopping, and sets its speed to the fastest from which it can still slow to {@value #BEND_SPEED}
 * mm/s by the next bend and stop at the track's end, braking at {@value #BRAKING} mm/s² (less
 * than the Pioneer's 300, so the profile holds however the steps fall). A robot that stands and
 * faces away from the track turns in place first. Its laser keeps it off anything on the track
 * ahead that is not a wall (a teammate the messages have not told of): it stops short of it. When
 * something stops it all the same it backs off a little.
 *
 * <p>The accelerations are the robot's own (its parameter file's); the driving never raises them.
 */
final class Driving {
    /** The fastest the robot drives, mm/s. */
    static final double TOP_SPEED = 1200;
    /** The fastest it takes a bend of half a cell's radius, mm/s (it cuts the bend a little). */
    static final double BEND_SPEED = 900;
    /** The deceleration its speed profile plans with, mm/s². */
    static final double BRAKING = 250;
    /** How far ahead on the track it steers for, mm: the way it drives in this many seconds... */
    private static final double LOOK_SECONDS = 1.0;
    /** ...but at least this far, mm. */
    private static final double LOOK_LEAST = 350;
    /** A standing robot facing further than this from the track turns in place first, degrees. */
    private static final double TURN_FIRST = 20;
    /** Echoes nearer the track ahead than this are in the way, mm: walls are at least 650 mm from it. */
    private static final double IN_THE_WAY = 450;
    /** The room it leaves before something in the way, beyond its front, mm. */
    private static final double CLEARANCE = 150;
    /** How far a robot backs off what it touches, mm. */
    private static final double BACK_OFF = 250;
    /** The longest a robot backs off an obstacle, steps. */
    private static final int BACK_STEPS = 30;

    private final ArRobot robot;
    private final ArSick laser;
    private final double dt;
    /** Whether it is turning in place to face the track. */
    private boolean turning;
    /** The step the robot began to back off. */
    private long backSince;
    /** Whether something on the track ahead stopped the robot at the last step. */
    private boolean blocked;

    /**
     * @param robot the robot
     * @param laser its laser, switched on
     */
    Driving(ArRobot robot, ArSick laser) {
        this.robot = robot;
        this.laser = laser;
        this.dt = robot.getStepMs() / 1000.0;
    }

    /**
     * Drives one step along the track.
     *
     * @param track the track from where the robot is
     * @return whether it has reached the track's end and stands there
     */
    boolean follow(Track track) {
        double v = robot.getVel();
        double toStop = track.toStop();
        if (toStop < 30 && Math.abs(v) < 60) {
            halt();
            return true;
        }
        double error = ArMath.fixAngle(track.headingHere() - robot.getTh());
        if (turning || (Math.abs(v) < 50 && Math.abs(error) > TURN_FIRST)) {
            turning = Math.abs(error) > 3 || Math.abs(robot.getRotVel()) > 15;
            if (turning) {
                robot.setVel(0);
                robot.setHeading(robot.getTh() + error);
                return false;
            }
        }
        double room = clearWay(track, toStop);
        blocked = room < toStop;
        // the speed asked for holds for a step: what it covers in that step is already spent
        double ahead = Math.max(0, Math.abs(v) * dt);
        double speed = Math.min(TOP_SPEED, Math.sqrt(2 * BRAKING * Math.max(0, room - ahead)));
        speed = Math.min(speed, Math.sqrt(BEND_SPEED * BEND_SPEED + 2 * BRAKING * Math.max(0, track.toBend() - ahead)));
        double look = Math.min(Math.max(LOOK_LEAST, LOOK_SECONDS * Math.abs(v)), TOP_SPEED * LOOK_SECONDS);
        double[] p = track.pointAhead(look);
        double dx = p[0] - robot.getX();
        double dy = p[1] - robot.getY();
        double dist = Math.hypot(dx, dy);
        double alpha = Math.toRadians(ArMath.fixAngle(Math.toDegrees(Math.atan2(dy, dx)) - robot.getTh()));
        if (dist < 100) {
            alpha = Math.toRadians(error);
            dist = Math.max(dist, 100);
        }
        speed *= Math.max(0, Math.cos(alpha)); // facing away from the point, slow down while turning to it
        double curvature = 2 * Math.sin(alpha) / dist;
        robot.setVel(speed);
        // the arc to the point at the speed it has, or at 100 mm/s while it starts, so that it turns from rest
        robot.setRotVel(Math.toDegrees(curvature * Math.max(Math.abs(v), 100)));
        return false;
    }

    /**
     * How far along the track the robot can drive before it comes within its front and a margin of
     * a laser echo lying on the track (not a wall: walls lie well off it).
     *
     * @param upTo how far ahead to look, mm
     * @return mm, at most {@code upTo}
     */
    private double clearWay(Track track, double upTo) {
        int[] scan = laser.getRawScan();
        if (scan.length < 2) {
            return upTo;
        }
        double increment = 180.0 / (scan.length - 1);
        double th = Math.toRadians(robot.getTh());
        double lx = robot.getX() + robot.getParameters().laserX() * Math.cos(th);
        double ly = robot.getY() + robot.getParameters().laserX() * Math.sin(th);
        double front = robot.getParameters().robotLengthFront() + CLEARANCE;
        double reach = upTo + front + IN_THE_WAY;
        double[] ex = new double[scan.length];
        double[] ey = new double[scan.length];
        int echoes = 0;
        for (int i = 0; i < scan.length; i++) {
            if (scan[i] < reach) {
                double a = th + Math.toRadians(i * increment - 90);
                ex[echoes] = lx + scan[i] * Math.cos(a);
                ey[echoes++] = ly + scan[i] * Math.sin(a);
            }
        }
        double near = IN_THE_WAY * IN_THE_WAY;
        for (double s = 0; s <= upTo + front; s += 100) {
            double[] q = track.pointAhead(s);
            for (int i = 0; i < echoes; i++) {
                double dx = ex[i] - q[0];
                double dy = ey[i] - q[1];
                if (dx * dx + dy * dy < near) {
                    return Math.max(0, Math.min(upTo, s - front));
                }
            }
        }
        return upTo;
    }

    /** @return whether something on the track ahead held the robot back at the last step */
    boolean blocked() {
        return blocked;
    }

    /** Stops where the robot is, at once. */
    void halt() {
        turning = false;
        robot.setVel(0);
        robot.setRotVel(0);
    }

    /** @return whether a collision stopped the robot */
    boolean isStalled() {
        return robot.isStalled();
    }

    /**
     * Stops and backs off a little from what it touches: back when the nearest echo (laser or
     * sonar) lies ahead of its centre, forward when it lies behind.
     */
    void backOff() {
        turning = false;
        robot.stop();
        robot.move(nearestEchoAhead() ? -BACK_OFF : BACK_OFF);
        backSince = robot.getStep();
    }

    /** @return whether the nearest echo, of the laser or a sonar, lies ahead of the robot's centre */
    private boolean nearestEchoAhead() {
        double th = Math.toRadians(robot.getTh());
        double ux = Math.cos(th);
        double uy = Math.sin(th);
        double best = Double.POSITIVE_INFINITY;
        double along = 1;
        int[] scan = laser.getRawScan();
        double increment = scan.length > 1 ? 180.0 / (scan.length - 1) : 1;
        double lx = robot.getParameters().laserX();
        for (int i = 0; i < scan.length; i++) {
            double a = Math.toRadians(i * increment - 90);
            double fx = lx + scan[i] * Math.cos(a);
            double fy = scan[i] * Math.sin(a);
            double d = Math.hypot(fx, fy);
            if (d < best) {
                best = d;
                along = fx;
            }
        }
        for (int i = 0; i < robot.getNumSonar(); i++) {
            var r = robot.getSonarReading(i);
            double fx = (r.getX() - robot.getX()) * ux + (r.getY() - robot.getY()) * uy;
            double fy = -(r.getX() - robot.getX()) * uy + (r.getY() - robot.getY()) * ux;
            double d = Math.hypot(fx, fy);
            if (r.getRange() > 0 && d < best) {
                best = d;
                along = fx;
            }
        }
        return along > 0;
    }

    /** @return whether backing off is over: done, blocked again, or taking too long */
    boolean backingOver() {
        boolean late = robot.getStep() - backSince > BACK_STEPS;
        return (robot.isMoveDone(1) && robot.isStopped()) || late
                || (robot.isStalled() && robot.getStep() - backSince > 2);
    }
}
