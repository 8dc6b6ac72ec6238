package robosim.env.core;

import robosim.geometry.Angles;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;

/**
 * The motion modes of a Pioneer's controller (see docs/ARIA-SEMANTICS.md): what translational and
 * rotational velocity the robot wants this step, given its commands and its pose. The velocities
 * it gets are then limited by its accelerations in {@link SimRobot}.
 *
 * <p>Translation is one of: a velocity, a move by a distance, wheel velocities (which also
 * decide rotation), or stopped. Rotation is one of: a velocity or holding a heading.
 */
final class DriveController {
    /** The deceleration ARIA's move profile assumes, mm/s²: v = sqrt(2 · 200 · distance to go). */
    static final double MOVE_PROFILE_DECEL = 200;
    /** A move ends when less than this is left to go, mm. */
    static final double MOVE_DONE = 0.5;
    /** A heading is held when within this, degrees. */
    static final double HEADING_DONE = 0.05;

    private enum Trans { VEL, MOVE, VEL2, WHEEL_MOVE }

    private enum Rot { VEL, HEADING, WHEELS }

    private final RobotParameters params;
    private double maxVel;
    private double maxRotVel;
    private Trans trans = Trans.VEL;
    private Rot rot = Rot.VEL;
    private double transVel;
    private double rotVel;
    private double left;
    private double right;
    private double moveStartX;
    private double moveStartY;
    private double moveDistance;
    private double heading;
    private boolean stopNow;
    private double leftToGo;
    private double rightToGo;
    private double transAccel;
    private double transDecel;
    private double rotAccel;
    private double rotDecel;

    DriveController(RobotParameters params) {
        this.params = params;
        this.maxVel = params.maxVelocity();
        this.maxRotVel = params.maxRVelocity();
        this.transAccel = params.transAccel();
        this.transDecel = params.transDecel();
        this.rotAccel = params.rotAccel();
        this.rotDecel = params.rotDecel();
    }

    /** Applies one motion command; the pose is the robot's pose as the command arrives. */
    void apply(Command.Motion command, double x, double y, double th) {
        if (command instanceof Command.SetVel c) {
            trans = Trans.VEL;
            transVel = c.vel();
            releaseWheels();
        } else if (command instanceof Command.SetRotVel c) {
            rot = Rot.VEL;
            rotVel = c.rotVel();
            releaseTranslation();
        } else if (command instanceof Command.SetVel2 c) {
            trans = Trans.VEL2;
            rot = Rot.WHEELS;
            left = c.left();
            right = c.right();
        } else if (command instanceof Command.Move c) {
            trans = Trans.MOVE;
            moveStartX = x;
            moveStartY = y;
            moveDistance = c.distance();
            releaseWheels();
        } else if (command instanceof Command.SetHeading c) {
            holdHeading(c.heading());
        } else if (command instanceof Command.SetDeltaHeading c) {
            holdHeading(th + c.delta());
        } else if (command instanceof Command.Stop) {
            stopNow = true;
            trans = Trans.VEL;
            rot = Rot.VEL;
            transVel = 0;
            rotVel = 0;
        } else if (command instanceof Command.MoveWheels c) {
            trans = Trans.WHEEL_MOVE;
            rot = Rot.WHEELS;
            leftToGo = c.left();
            rightToGo = c.right();
        } else if (command instanceof Command.SetAccel c) {
            transAccel = c.trans();
            transDecel = c.trans();
            rotAccel = c.rot();
            rotDecel = c.rot();
        } else if (command instanceof Command.SetDriveLimit c) {
            double v = Math.min(c.value(), RobotParameters.MAX_ACCELERATION);
            switch (c.limit()) {
                case TRANS_ACCEL -> transAccel = v;
                case TRANS_DECEL -> transDecel = v;
                case ROT_ACCEL -> rotAccel = v;
                case ROT_DECEL -> rotDecel = v;
                default -> throw new IllegalStateException("no drive limit " + c.limit());
            }
        } else if (command instanceof Command.SetMaxTransVel c) {
            maxVel = Math.max(0, Math.min(c.vel(), params.maxVelocity()));
        } else if (command instanceof Command.SetMaxRotVel c) {
            maxRotVel = Math.max(0, Math.min(c.rotVel(), params.maxRVelocity()));
        } else {
            throw new IllegalStateException("the drive controller has no rule for " + command);
        }
    }

    private void holdHeading(double target) {
        rot = Rot.HEADING;
        heading = Angles.fix(target);
        releaseTranslation();
    }

    /** Leaving wheel-velocity mode for rotation: translation keeps the wheels' mean speed. */
    private void releaseTranslation() {
        if (trans == Trans.WHEEL_MOVE) {
            trans = Trans.VEL;
            transVel = 0;
        } else if (trans == Trans.VEL2) {
            trans = Trans.VEL;
            transVel = (left + right) / 2;
        }
    }

    /** Leaving wheel-velocity mode for translation: rotation stops. */
    private void releaseWheels() {
        if (rot == Rot.WHEELS) {
            rot = Rot.VEL;
            rotVel = 0;
        }
    }

    /**
     * A stop halts the robot at once, bypassing the decelerations, as ARIA's STOP command does.
     *
     * @return whether a stop arrived since the last call
     */
    boolean takeStop() {
        boolean s = stopNow;
        stopNow = false;
        return s;
    }

    /**
     * The translational velocity wanted now, mm/s.
     *
     * @param vel the velocity now, mm/s: a move asks for the speed after whose step it is still on its
     *            braking profile
     */
    double wantedVel(double x, double y, double dt, double vel) {
        double v = switch (trans) {
            case VEL -> transVel;
            case VEL2 -> (left + right) / 2;
            case WHEEL_MOVE -> planWheels(dt);
            case MOVE -> {
                double toGo = Math.abs(moveDistance) - Math.hypot(x - moveStartX, y - moveStartY);
                if (toGo < MOVE_DONE) {
                    trans = Trans.VEL;
                    transVel = 0;
                    yield 0;
                }
                double speed = SpeedProfile.onProfile(toGo, Math.copySign(1, moveDistance) * vel, MOVE_PROFILE_DECEL,
                        transAccel, transDecel, dt, maxVel);
                yield Math.copySign(speed, moveDistance);
            }
        };
        return clamp(v, maxVel);
    }

    /**
     * Sets this step's wheel speeds for a wheel move: the wheel with farther to go follows the move
     * profile, the other keeps the same proportion, so both finish together.
     *
     * @return the translational velocity wanted, mm/s
     */
    private double planWheels(double dt) {
        double far = Math.max(Math.abs(leftToGo), Math.abs(rightToGo));
        if (far < MOVE_DONE) {
            trans = Trans.VEL;
            transVel = 0;
            rot = Rot.VEL;
            rotVel = 0;
            left = 0;
            right = 0;
            return 0;
        }
        double speed = Math.min(Math.min(maxVel, Math.sqrt(2 * MOVE_PROFILE_DECEL * far)), far / dt);
        left = speed * leftToGo / far;
        right = speed * rightToGo / far;
        return (left + right) / 2;
    }

    /**
     * Tells a wheel move how far the wheels actually went this step (less than planned when the
     * accelerations or a collision held the robot back).
     *
     * @param leftMm  the left wheel's travel
     * @param rightMm the right wheel's travel
     */
    void travelled(double leftMm, double rightMm) {
        if (trans == Trans.WHEEL_MOVE) {
            leftToGo -= leftMm;
            rightToGo -= rightMm;
        }
    }

    double transAccel() {
        return transAccel;
    }

    double transDecel() {
        return transDecel;
    }

    double rotAccel() {
        return rotAccel;
    }

    double rotDecel() {
        return rotDecel;
    }

    /**
     * The rotational velocity wanted now, deg/s.
     *
     * @param turning the rotational velocity now, deg/s: a heading asks for the speed after whose step
     *                it is still on its braking profile
     */
    double wantedRotVel(double th, double dt, double turning) {
        double w = switch (rot) {
            case VEL -> rotVel;
            case WHEELS -> Math.toDegrees((right - left) / 2 * params.diffConvFactor());
            case HEADING -> {
                double err = Angles.fix(heading - th);
                if (Math.abs(err) < HEADING_DONE) {
                    yield 0;
                }
                double speed = SpeedProfile.onProfile(Math.abs(err), Math.signum(err) * turning, rotDecel, rotAccel,
                        rotDecel, dt, maxRotVel);
                yield Math.copySign(speed, err);
            }
        };
        return clamp(w, maxRotVel);
    }

    private static double clamp(double v, double limit) {
        return Math.max(-limit, Math.min(limit, v));
    }
}
