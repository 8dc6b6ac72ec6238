package robosim.aria;

import robosim.protocol.Command;
import robosim.protocol.RobotParameters;

/**
 * {@link ArRobot}'s motion: the motion commands (none of them blocks), the velocity limits,
 * accelerations and decelerations, the absolute maxima, the negative and lateral limits, the done
 * tests, and the direct commands' hold on the actions, as ARIA's {@code ArRobot} has them
 * (ArRobot.cpp). The highest of the package-private layers that {@link ArRobot}, the public face, is
 * made of.
 */
abstract class ArRobotMotion extends ArRobotPose {
    private volatile ArPose moveStart;
    private volatile double moveDistance;
    private volatile Double headingTarget;
    private volatile double transAsked;
    private volatile double rotAsked;
    private volatile double maxTransVel;
    private volatile double maxRotVel;
    private final DriveLimits driveLimits = new DriveLimits();
    /** The absolute maxima, the negative velocity limit and the lateral limits. */
    private final Maxima maxima = new Maxima();
    private volatile double moveDoneDist = ArRobot.DEFAULT_MOVE_DONE;
    private volatile double headingDoneDiff = ArRobot.DEFAULT_HEADING_DONE;

    /** The robot, named and placed, with its parameters: see {@link ArRobot}'s constructors. */
    ArRobotMotion(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, parameters);
    }

    /** The velocity limits and absolute maxima the parameters give, after the layers below have taken theirs. */
    @Override
    void useParameters(RobotParameters parameters) {
        super.useParameters(parameters);
        this.maxTransVel = parameters.maxVelocity();
        this.maxRotVel = parameters.maxRVelocity();
        maxima.reset(parameters);
    }

    // ---- motion: none of these block ----

    /**
     * Travels a distance from the current pose; negative is backwards.
     *
     * @param distance mm
     * @throws IllegalArgumentException if it is not finite
     */
    public void move(double distance) {
        Command.Move move = new Command.Move(distance);
        moveStart = getPose();
        moveDistance = distance;
        transAsked = 0;
        request(move);
        actions.directTrans(simulatedMs());
    }

    /** Translational and rotational velocity to zero at once. */
    public void stop() {
        moveStart = null;
        headingTarget = null;
        transAsked = 0;
        rotAsked = 0;
        request(new Command.Stop());
        actions.stopped(simulatedMs());
    }

    /**
     * @param velocity mm/s, rounded and clamped to the maximum translational velocity, and backwards
     *                 to {@link #getTransNegVelMax()}, as ARIA's state reflection clamps it
     * @throws IllegalArgumentException if it is not finite
     */
    public void setVel(double velocity) {
        Command.SetVel vel = new Command.SetVel(Math.rint(Math.max(velocity, maxima.transNegVelMax())));
        moveStart = null;
        transAsked = Math.abs(vel.vel());
        request(vel);
        actions.directTrans(simulatedMs());
    }

    /**
     * @param velocity deg/s, counter-clockwise positive, clamped to the maximum rotational velocity
     * @throws IllegalArgumentException if it is not finite
     */
    public void setRotVel(double velocity) {
        Command.SetRotVel rotVel = new Command.SetRotVel(velocity);
        headingTarget = null;
        rotAsked = Math.abs(velocity);
        request(rotVel);
        actions.directRot(simulatedMs());
    }

    /**
     * Sets the wheel velocities; cancels any rotation command.
     *
     * @param leftVelocity  mm/s
     * @param rightVelocity mm/s
     * @throws IllegalArgumentException if either is not finite
     */
    public void setVel2(double leftVelocity, double rightVelocity) {
        Command.SetVel2 vel2 = new Command.SetVel2(leftVelocity, rightVelocity);
        moveStart = null;
        headingTarget = null;
        transAsked = Math.max(Math.abs(leftVelocity), Math.abs(rightVelocity));
        rotAsked = 0;
        request(vel2);
        actions.directTrans(simulatedMs());
        actions.directRot(simulatedMs());
    }

    /**
     * @param heading absolute heading to turn to, degrees
     * @throws IllegalArgumentException if it is not finite
     */
    public void setHeading(double heading) {
        Command.SetHeading turn = new Command.SetHeading(heading);
        headingTarget = ArMath.fixAngle(heading);
        request(new Command.SetHeading(encoderHeading(heading)));
        actions.directRot(simulatedMs());
    }

    /**
     * @param delta degrees to turn from the current heading
     * @throws IllegalArgumentException if it is not finite
     */
    public void setDeltaHeading(double delta) {
        Command.SetDeltaHeading turn = new Command.SetDeltaHeading(delta);
        headingTarget = ArMath.fixAngle(getTh() + delta);
        request(turn);
        actions.directRot(simulatedMs());
    }

    /**
     * @param velocity new translational limit, mm/s, within the parameter file's maximum
     * @throws IllegalArgumentException if it is not finite
     */
    public void setMaxTransVel(double velocity) {
        Command.SetMaxTransVel limit = new Command.SetMaxTransVel(Math.min(velocity, getAbsoluteMaxTransVel()));
        maxTransVel = Math.max(0, Math.min(velocity, getAbsoluteMaxTransVel()));
        request(limit);
    }

    /**
     * @param velocity new rotational limit, deg/s, within the parameter file's maximum
     * @throws IllegalArgumentException if it is not finite
     */
    public void setMaxRotVel(double velocity) {
        Command.SetMaxRotVel limit = new Command.SetMaxRotVel(Math.min(velocity, getAbsoluteMaxRotVel()));
        maxRotVel = Math.max(0, Math.min(velocity, getAbsoluteMaxRotVel()));
        request(limit);
    }

    /** @return the translational limit, mm/s */
    public double getMaxTransVel() {
        return maxTransVel;
    }

    /**
     * ARIA's name for the translational velocity limit: as {@link #setMaxTransVel}, except that a
     * value of 0 or less is ignored with a log line, as ARIA's {@code setTransVelMax} ignores it (the
     * original RoboSim's {@code setMaxTransVel} sets a zero limit).
     *
     * @param vel the new limit, mm/s; capped at {@link #getAbsoluteMaxTransVel()} with ARIA's log line
     */
    public void setTransVelMax(double vel) {
        if (!DriveLimits.ignoresVelocity("setTransVelMax", vel, getName())) {
            double abs = getAbsoluteMaxTransVel();
            if (vel > abs) {
                LOG.warning(() -> "robot " + getName() + ": ArRobot: setTransVelMax of " + vel
                        + " is over the absolute max vel of " + abs + ", capping it");
            }
            setMaxTransVel(vel);
        }
    }

    /** @return the translational velocity limit, mm/s (ARIA's name for {@link #getMaxTransVel}) */
    public double getTransVelMax() {
        return getMaxTransVel();
    }

    /**
     * ARIA's name for the rotational velocity limit; a value of 0 or less is ignored with a log line.
     *
     * @param vel the new limit, deg/s; capped at {@link #getAbsoluteMaxRotVel()} with ARIA's log line
     */
    public void setRotVelMax(double vel) {
        if (!DriveLimits.ignoresVelocity("setRotVelMax", vel, getName())) {
            double abs = getAbsoluteMaxRotVel();
            if (vel > abs) {
                LOG.warning(() -> "robot " + getName() + ": ArRobot: setRotVelMax of " + vel
                        + " is over the absolute max vel of " + abs + ", capping it");
            }
            setMaxRotVel(vel);
        }
    }

    /** @return the rotational velocity limit, deg/s (ARIA's name for {@link #getMaxRotVel}) */
    public double getRotVelMax() {
        return getMaxRotVel();
    }

    /** @param acc the translational acceleration, mm/s²; 0 or less is ignored, as in ARIA */
    public void setTransAccel(double acc) {
        setDriveLimit(Command.DriveLimit.TRANS_ACCEL, acc);
    }

    /** @param decel the translational deceleration, mm/s²; 0 or less is ignored, as in ARIA */
    public void setTransDecel(double decel) {
        setDriveLimit(Command.DriveLimit.TRANS_DECEL, decel);
    }

    /** @param acc the rotational acceleration, deg/s²; 0 or less is ignored, as in ARIA */
    public void setRotAccel(double acc) {
        setDriveLimit(Command.DriveLimit.ROT_ACCEL, acc);
    }

    /** @param decel the rotational deceleration, deg/s²; 0 or less is ignored, as in ARIA */
    public void setRotDecel(double decel) {
        setDriveLimit(Command.DriveLimit.ROT_DECEL, decel);
    }

    /** @return the translational acceleration in force, mm/s² (the parameter file's until set) */
    public double getTransAccel() {
        return driveLimits.get(Command.DriveLimit.TRANS_ACCEL, getParameters());
    }

    /** @return the translational deceleration in force, mm/s² (the parameter file's until set) */
    public double getTransDecel() {
        return driveLimits.get(Command.DriveLimit.TRANS_DECEL, getParameters());
    }

    /** @return the rotational acceleration in force, deg/s² (the parameter file's until set) */
    public double getRotAccel() {
        return driveLimits.get(Command.DriveLimit.ROT_ACCEL, getParameters());
    }

    /** @return the rotational deceleration in force, deg/s² (the parameter file's until set) */
    public double getRotDecel() {
        return driveLimits.get(Command.DriveLimit.ROT_DECEL, getParameters());
    }

    private void setDriveLimit(Command.DriveLimit limit, double value) {
        Command.SetDriveLimit c = driveLimits.set(limit, value, getName(), maxima.get(switch (limit) {
            case TRANS_ACCEL -> Maxima.Absolute.TRANS_ACCEL;
            case TRANS_DECEL -> Maxima.Absolute.TRANS_DECEL;
            case ROT_ACCEL -> Maxima.Absolute.ROT_ACCEL;
            case ROT_DECEL -> Maxima.Absolute.ROT_DECEL;
        }));
        if (c != null) {
            request(c);
        }
    }

    /** @return the rotational limit, deg/s */
    public double getMaxRotVel() {
        return maxRotVel;
    }

    // ---- absolute maxima, the negative and lateral limits ----

    /** @return the absolute maximum translational velocity, mm/s: the parameter file's {@code MaxVelocity} until set */
    public double getAbsoluteMaxTransVel() {
        return maxima.get(Maxima.Absolute.TRANS_VEL);
    }

    /**
     * Sets the absolute maximum translational velocity, as ARIA's {@code ArRobot::setAbsoluteMaxTransVel} (ArRobot.cpp)
     * (ArRobot.cpp): 0 or less is refused with a log line; over the top (the parameter file's
     * {@code MaxVelocity}, what the Environment drives) is capped with a log line; a velocity limit
     * above the new maximum comes down to it.
     *
     * @param maxVel mm/s
     * @return false if refused
     */
    public boolean setAbsoluteMaxTransVel(double maxVel) {
        Double v = maxima.set(Maxima.Absolute.TRANS_VEL, maxVel, getName());
        if (v != null && getTransVelMax() > v) {
            setTransVelMax(v);
        }
        return v != null;
    }

    /** @return the absolute maximum backwards velocity, mm/s, negative: −{@code MaxVelocity} until set */
    public double getAbsoluteMaxTransNegVel() {
        return maxima.get(Maxima.Absolute.TRANS_NEG_VEL);
    }

    /**
     * As {@link #setAbsoluteMaxTransVel} for backwards (ARIA's {@code ArRobot::setAbsoluteMaxTransNegVel}
     * (ArRobot.cpp)): 0 or more is refused, below −{@code MaxVelocity} capped, each with a log line; a
     * {@link #getTransNegVelMax()} below the new maximum comes up to it.
     *
     * @param maxNegVel mm/s, negative
     * @return false if refused
     */
    public boolean setAbsoluteMaxTransNegVel(double maxNegVel) {
        return maxima.set(Maxima.Absolute.TRANS_NEG_VEL, maxNegVel, getName()) != null;
    }

    /** @return the absolute maximum translational acceleration, mm/s² (the Environment's largest until set) */
    public double getAbsoluteMaxTransAccel() {
        return maxima.get(Maxima.Absolute.TRANS_ACCEL);
    }

    /**
     * ARIA's {@code ArRobot::setAbsoluteMaxTransAccel} (ArRobot.cpp): 0 or less refused, over the Environment's largest
     * capped, each with a log line; an acceleration above it comes down to it.
     *
     * @param maxAccel mm/s²
     * @return false if refused
     */
    public boolean setAbsoluteMaxTransAccel(double maxAccel) {
        return setAbsolute(Maxima.Absolute.TRANS_ACCEL, maxAccel, Command.DriveLimit.TRANS_ACCEL);
    }

    /** @return the absolute maximum translational deceleration, mm/s² */
    public double getAbsoluteMaxTransDecel() {
        return maxima.get(Maxima.Absolute.TRANS_DECEL);
    }

    /** @param maxDecel mm/s², as {@link #setAbsoluteMaxTransAccel} @return false if refused */
    public boolean setAbsoluteMaxTransDecel(double maxDecel) {
        return setAbsolute(Maxima.Absolute.TRANS_DECEL, maxDecel, Command.DriveLimit.TRANS_DECEL);
    }

    /** @return the absolute maximum rotational velocity, deg/s: the parameter file's {@code MaxRVelocity} until set */
    public double getAbsoluteMaxRotVel() {
        return maxima.get(Maxima.Absolute.ROT_VEL);
    }

    /**
     * ARIA's {@code ArRobot::setAbsoluteMaxRotVel} (ArRobot.cpp): 0 or less refused, over {@code
     * MaxRVelocity} capped, each with a log line; a rotational limit above it comes down to it.
     *
     * @param maxVel deg/s
     * @return false if refused
     */
    public boolean setAbsoluteMaxRotVel(double maxVel) {
        Double v = maxima.set(Maxima.Absolute.ROT_VEL, maxVel, getName());
        if (v != null && getRotVelMax() > v) {
            setRotVelMax(v);
        }
        return v != null;
    }

    /** @return the absolute maximum rotational acceleration, deg/s² */
    public double getAbsoluteMaxRotAccel() {
        return maxima.get(Maxima.Absolute.ROT_ACCEL);
    }

    /** @param maxAccel deg/s², as {@link #setAbsoluteMaxTransAccel} @return false if refused */
    public boolean setAbsoluteMaxRotAccel(double maxAccel) {
        return setAbsolute(Maxima.Absolute.ROT_ACCEL, maxAccel, Command.DriveLimit.ROT_ACCEL);
    }

    /** @return the absolute maximum rotational deceleration, deg/s² */
    public double getAbsoluteMaxRotDecel() {
        return maxima.get(Maxima.Absolute.ROT_DECEL);
    }

    /** @param maxDecel deg/s², as {@link #setAbsoluteMaxTransAccel} @return false if refused */
    public boolean setAbsoluteMaxRotDecel(double maxDecel) {
        return setAbsolute(Maxima.Absolute.ROT_DECEL, maxDecel, Command.DriveLimit.ROT_DECEL);
    }

    private boolean setAbsolute(Maxima.Absolute which, double value, Command.DriveLimit limit) {
        Double v = maxima.set(which, value, getName());
        if (v != null && driveLimits.get(limit, getParameters()) > v) {
            setDriveLimit(limit, v);
        }
        return v != null;
    }

    /**
     * @return 0: the absolute maximum lateral velocity of a robot without lateral motion (a Pioneer's
     *     config packet's)
     */
    public double getAbsoluteMaxLatVel() {
        return maxima.get(Maxima.Absolute.LAT_VEL);
    }

    /**
     * ARIA's {@code ArRobot::setAbsoluteMaxLatVel} (ArRobot.cpp): 0 or less refused with a log line;
     * anything else capped to the top, 0 for a robot without lateral motion, with a log line.
     *
     * @param maxVel mm/s
     * @return false if refused
     */
    public boolean setAbsoluteMaxLatVel(double maxVel) {
        return maxima.set(Maxima.Absolute.LAT_VEL, maxVel, getName()) != null;
    }

    /** @return 0: the absolute maximum lateral acceleration of a robot without lateral motion */
    public double getAbsoluteMaxLatAccel() {
        return maxima.get(Maxima.Absolute.LAT_ACCEL);
    }

    /** @param maxAccel mm/s², as {@link #setAbsoluteMaxLatVel} @return false if refused */
    public boolean setAbsoluteMaxLatAccel(double maxAccel) {
        return maxima.set(Maxima.Absolute.LAT_ACCEL, maxAccel, getName()) != null;
    }

    /** @return 0: the absolute maximum lateral deceleration of a robot without lateral motion */
    public double getAbsoluteMaxLatDecel() {
        return maxima.get(Maxima.Absolute.LAT_DECEL);
    }

    /** @param maxDecel mm/s², as {@link #setAbsoluteMaxLatVel} @return false if refused */
    public boolean setAbsoluteMaxLatDecel(double maxDecel) {
        return maxima.set(Maxima.Absolute.LAT_DECEL, maxDecel, getName()) != null;
    }

    /** @return the backwards velocity limit, mm/s, negative: −{@code MaxVelocity} until set */
    public double getTransNegVelMax() {
        return maxima.transNegVelMax();
    }

    /**
     * ARIA's {@code ArRobot::setTransNegVelMax} (ArRobot.cpp): 0 or more is ignored, below {@link
     * #getAbsoluteMaxTransNegVel()} is capped, each with ARIA's log line. {@link #setVel} clamps backwards
     * velocities to it.
     *
     * @param negVel mm/s, negative
     */
    public void setTransNegVelMax(double negVel) {
        maxima.setTransNegVelMax(negVel, getName());
    }

    /** @return false: RoboSim's robots (Pioneers, as the parameter files give them) have no lateral motion */
    public boolean hasLatVel() {
        return false;
    }

    /** @return 0: the lateral velocity of a robot without lateral motion */
    public double getLatVel() {
        return 0;
    }

    /**
     * ARIA's {@code ArRobot::setLatVel} (ArRobot.cpp): a robot without lateral motion ({@link
     * #hasLatVel()} false) is sent nothing, as ARIA's state reflection sends no lateral command to it.
     *
     * @param latVelocity mm/s
     */
    public void setLatVel(double latVelocity) {
        LOG.fine(() -> "robot " + getName() + ": setLatVel(" + latVelocity + "): the robot has no lateral motion");
    }

    /** @return the lateral velocity limit: 0 for a robot without lateral motion */
    public double getLatVelMax() {
        return maxima.latVelMax();
    }

    /** @param vel mm/s: 0 or less ignored, over the absolute maximum (0) capped, logged at ARIA's verbose level */
    public void setLatVelMax(double vel) {
        maxima.setLateral(Maxima.Absolute.LAT_VEL, vel, getName());
    }

    /** @return the lateral acceleration: 0 for a robot without lateral motion */
    public double getLatAccel() {
        return maxima.latAccel();
    }

    /** @param acc mm/s², as {@link #setLatVelMax} */
    public void setLatAccel(double acc) {
        maxima.setLateral(Maxima.Absolute.LAT_ACCEL, acc, getName());
    }

    /** @return the lateral deceleration: 0 for a robot without lateral motion */
    public double getLatDecel() {
        return maxima.latDecel();
    }

    /** @param decel mm/s², as {@link #setLatVelMax} */
    public void setLatDecel(double decel) {
        maxima.setLateral(Maxima.Absolute.LAT_DECEL, decel, getName());
    }

    /** @return true: the velocity limits are sent to the Environment, as a Pioneer's are ({@code SettableVelMaxes}) */
    public boolean hasSettableVelMaxes() {
        return true;
    }

    /** @return true: the accelerations are sent to the Environment, as a Pioneer's are ({@code SettableAccsDecs}) */
    public boolean hasSettableAccsDecs() {
        return true;
    }

    // ---- done tests ----

    /** @return whether the last move is done, within {@link #getMoveDoneDist()} mm */
    public boolean isMoveDone() {
        return isMoveDone(0);
    }

    /**
     * @param delta how close counts as done, mm; 0 (below 0.001 either way, as in ARIA) means
     *              {@link #getMoveDoneDist()}
     * @return true if no move is active, else whether the robot is at least |distance| − delta from
     *         where the move started
     */
    public boolean isMoveDone(double delta) {
        ArPose start = moveStart;
        if (start == null) {
            return true;
        }
        double d = Math.abs(delta) < 0.001 ? moveDoneDist : delta;
        return start.findDistanceTo(getPose()) >= Math.abs(moveDistance) - d;
    }

    /** @return whether the heading is reached, within {@link #getHeadingDoneDiff()}° */
    public boolean isHeadingDone() {
        return isHeadingDone(0);
    }

    /**
     * @param delta how close counts as done, degrees; 0 (below 0.001 either way, as in ARIA) means
     *              {@link #getHeadingDoneDiff()}
     * @return true if no heading command is active, else whether |heading − target| ≤ delta
     */
    public boolean isHeadingDone(double delta) {
        Double target = headingTarget;
        if (target == null) {
            return true;
        }
        double d = Math.abs(delta) < 0.001 ? headingDoneDiff : delta;
        return Math.abs(ArMath.subAngle(getTh(), target)) <= d;
    }

    /** @param dist how close to a move's distance {@link #isMoveDone()} counts as done, mm (ARIA's default 40) */
    public void setMoveDoneDist(double dist) {
        moveDoneDist = dist;
    }

    /** @return how close to a move's distance {@link #isMoveDone()} counts as done, mm */
    public double getMoveDoneDist() {
        return moveDoneDist;
    }

    /** @param degrees how close to a heading {@link #isHeadingDone()} counts as done (ARIA's default 3) */
    public void setHeadingDoneDiff(double degrees) {
        headingDoneDiff = degrees;
    }

    /** @return how close to a heading {@link #isHeadingDone()} counts as done, degrees */
    public double getHeadingDoneDiff() {
        return headingDoneDiff;
    }

    // ---- direct motion and the actions ----

    /**
     * Gives motion back to the actions after direct motion commands, and forgets the actions' last
     * values so that what they want is sent again (ARIA's {@code clearDirectMotion}).
     */
    public void clearDirectMotion() {
        actions.clearDirectMotion();
    }

    /**
     * @param ms how long a direct motion command keeps its channel from the actions, simulated ms;
     *           0 (ARIA's default) means until {@link #clearDirectMotion()}
     */
    public void setDirectMotionPrecedenceTime(int ms) {
        actions.setPrecedenceMs(ms);
    }

    /** @return how long a direct motion command keeps its channel from the actions, ms; 0 means until cleared */
    public long getDirectMotionPrecedenceTime() {
        return actions.precedenceMs();
    }

    /** @return whether a direct motion command holds translation or rotation now */
    public boolean isDirectMotion() {
        long now = simulatedMs();
        return actions.transDirect(now) || actions.rotDirect(now);
    }

    /**
     * Whether the robot is trying to move, as ARIA's state reflection decides it each cycle: a
     * velocity asked of more than 0.5 mm/s or deg/s (directly or by the actions), a move not yet
     * done, a heading more than 1° away; or {@link #forceTryingToMove()} in this cycle.
     *
     * @return whether the robot is trying to move
     */
    public boolean isTryingToMove() {
        if (forcedTryingToMove) {
            return true;
        }
        long now = simulatedMs();
        boolean trans;
        if (actions.transDirect(now)) {
            trans = moveStart != null ? !isMoveDone() : transAsked > 0.5;
        } else {
            ArActionDesired d = actions.lastDesired();
            trans = d.getVelStrength() > 0 && Math.abs(d.getVel()) > 0.5;
        }
        boolean rot;
        if (actions.rotDirect(now)) {
            Double target = headingTarget;
            rot = target != null ? Math.abs(ArMath.subAngle(getTh(), target)) > 1 : rotAsked > 0.5;
        } else {
            ArActionDesired d = actions.lastDesired();
            rot = d.getRotVelStrength() > 0 && Math.abs(d.getRotVel()) > 0.5
                    || d.getDeltaHeadingStrength() > 0 && Math.abs(d.getDeltaHeading()) > 1;
        }
        return trans || rot;
    }

    /**
     * Makes {@link #isTryingToMove()} true until the end of the current cycle, as ARIA's {@code
     * ArRobot::forceTryingToMove} (ArRobot.h).
     */
    public void forceTryingToMove() {
        forcedTryingToMove = true;
    }

    /**
     * @return the state reflection's refresh time, ms (ARIA's default 500): ARIA resends an unchanged
     *         motion command this often; the Environment keeps a command until the next, so nothing is
     *         resent here
     */
    public int getStateReflectionRefreshTime() {
        return extras.refreshMs;
    }

    /** @param msec the refresh time, ms; below 0 means 0, as in ARIA */
    public void setStateReflectionRefreshTime(int msec) {
        extras.refreshMs = Math.max(0, msec);
    }
}
