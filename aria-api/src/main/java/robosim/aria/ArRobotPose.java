package robosim.aria;

import robosim.protocol.BatteryReading;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;

/**
 * {@link ArRobot}'s pose: position, velocities and odometers, the stopped test, the pose's frames
 * (raw encoder, encoder, global) and their histories, moving the frame ({@code moveTo}) with the range
 * devices' readings, and the queries over the range devices, as ARIA's {@code ArRobot} has them
 * (ArRobot.cpp, ArRobot.h); it takes each state's readings into the robot. One of the package-private
 * layers that {@link ArRobot}, the public face, is made of.
 */
abstract class ArRobotPose extends ArRobotDevices {
    /** ARIA's virtual odometer and trip odometer. */
    private final Odometer odometer = new Odometer();
    private volatile double stoppedVel = ArRobot.STOPPED_VEL;
    private volatile double stoppedRotVel = ArRobot.STOPPED_ROT_VEL;
    /** The raw encoder, encoder and global poses' frames over the Environment's pose. */
    private final PoseFrames frames = new PoseFrames();
    /** The latest global and encoder poses, for ARIA's interpolation calls. */
    private final PoseHistory poseHistory = new PoseHistory();
    private final PoseHistory encoderPoseHistory = new PoseHistory();
    private volatile int odometryDelayMs;
    /** The attached range devices. */
    final RangeDevices rangeDevices = new RangeDevices();

    /** The robot, named and placed, with its parameters: see {@link ArRobot}'s constructors. */
    ArRobotPose(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, parameters);
    }

    // ---- each state's readings ----

    /**
     * Takes one state's readings in, in the cycle's order: the sonar ring, the odometers,
     * the wheel encoders, the logging asked for, the battery, the counts of states, the pose histories.
     */
    @Override
    void readState(RobotState s) {
        SonarReading ring = s.get(SonarReading.PART);
        sonar.update(ring.ranges(), ring.fresh(), getPose(), counter, s.timeMs());
        odometer.update(s);
        wheelEncoders.update(s);
        logReceived(s);
        battery.update(s.get(BatteryReading.PART), s.timeMs());
        cycleStats.count(s.timeMs(), ring.ranges().length > 0);
        long odometryMs = s.timeMs() - odometryDelayMs;
        poseHistory.add(getPose(), odometryMs);
        encoderPoseHistory.add(getEncoderPose(), odometryMs);
    }

    /** The logging a program turned on for each state received. */
    private void logReceived(RobotState s) {
        if (extras.packetsReceivedTracking) {
            LOG.info(() -> "robot " + getName() + ": received the state of step " + s.step() + " at "
                    + s.timeMs() + " ms");
        }
        if (extras.logSipContents) {
            LOG.info(() -> "robot " + getName() + ": state " + s);
        }
        if (extras.logMovementReceived) {
            LOG.info(() -> "robot " + getName() + ": pose " + getPose() + " (encoder " + getEncoderPose() + ")");
        }
        if (extras.logVelocitiesReceived) {
            LOG.info(() -> "robot " + getName() + ": vel " + s.vel() + " rotVel " + s.rotVel() + " left " + s.leftVel()
                    + " right " + s.rightVel() + " th " + getTh());
        }
    }

    @Override
    void restartTripOdometer() {
        resetTripOdometer();
    }

    // ---- state ----

    /** @return odometry x, mm (in the frame {@link #moveTo} set, if it was called) */
    public double getX() {
        return getPose().getX();
    }

    /** @return odometry y, mm (in the frame {@link #moveTo} set, if it was called) */
    public double getY() {
        return getPose().getY();
    }

    /** @return odometry heading, degrees in (-180, 180] (in the frame {@link #moveTo} set) */
    public double getTh() {
        return getPose().getTh();
    }

    /**
     * @return the odometry pose, a new object: the encoder pose ({@link #getEncoderPose()}) carried
     *         into the frame {@link #moveTo} set, as ARIA's encoder transform carries it
     */
    public ArPose getPose() {
        return frames.global(state());
    }

    /** @param pose a pose @return the distance from the robot's pose to it, mm */
    public double findDistanceTo(ArPose pose) {
        return getPose().findDistanceTo(pose);
    }

    /** @param pose a pose @return the angle from the robot's position to it, degrees */
    public double findAngleTo(ArPose pose) {
        return getPose().findAngleTo(pose);
    }

    /** @param pose a pose @return how far the robot must turn to face it, degrees in (−180, 180] */
    public double findDeltaHeadingTo(ArPose pose) {
        ArPose p = getPose();
        return ArMath.subAngle(p.findAngleTo(pose), p.getTh());
    }

    /** @return translational velocity, (left + right) / 2, mm/s */
    public double getVel() {
        return state().vel();
    }

    /** @return rotational velocity, deg/s */
    public double getRotVel() {
        return state().rotVel();
    }

    /** @return left wheel velocity, mm/s */
    public double getLeftVel() {
        return state().leftVel();
    }

    /** @return right wheel velocity, mm/s */
    public double getRightVel() {
        return state().rightVel();
    }

    /** @return whether a collision stopped the robot's last motion */
    public boolean isStalled() {
        return state().stalled();
    }

    /**
     * @return the distance travelled since the program connected, mm: ARIA's virtual odometer, the
     *         sum over the cycles of the straight line between one odometry pose and the next
     */
    public double getOdometerDistance() {
        return odometer.distance();
    }

    /** @return the degrees turned since the program connected: the sum of each cycle's absolute heading change */
    public double getOdometerDegrees() {
        return odometer.degrees();
    }

    /** @return the simulated seconds since the program connected, whole */
    public long getOdometerTime() {
        return odometer.seconds();
    }

    /** @return {@link #getOdometerDistance()} in metres */
    public double getOdometerDistanceMeters() {
        return getOdometerDistance() / 1000.0;
    }

    /** @return {@link #getOdometerTime()} in minutes, with the fraction */
    public double getOdometerTimeMinutes() {
        return getOdometerTime() / 60.0;
    }

    /** @return the distance travelled since {@link #resetTripOdometer()} (or since connecting), mm */
    public double getTripOdometerDistance() {
        return odometer.tripDistance();
    }

    /** @return the degrees turned since {@link #resetTripOdometer()} (or since connecting) */
    public double getTripOdometerDegrees() {
        return odometer.tripDegrees();
    }

    /** @return the simulated seconds since {@link #resetTripOdometer()} (or since connecting), whole */
    public long getTripOdometerTime() {
        return odometer.tripSeconds();
    }

    /** Starts the trip odometer again: its distance, degrees and time count from now. */
    public void resetTripOdometer() {
        odometer.resetTrip();
    }

    /**
     * @return whether the robot is stopped: at most the stopped velocities ({@link #setStoppedVels},
     *         ARIA's 4 mm/s and 1 deg/s by default)
     */
    public boolean isStopped() {
        return isStopped(0, 0);
    }

    /**
     * @param vel    the translational speed that counts as stopped, mm/s; below 0.001 means the
     *               robot's own ({@link #setStoppedVels}), as in ARIA
     * @param rotVel the rotational speed that counts as stopped, deg/s; below 0.001 likewise
     * @return whether |velocity| and |rotational velocity| are at most these
     */
    public boolean isStopped(double vel, double rotVel) {
        double v = vel < 0.001 ? stoppedVel : vel;
        double r = rotVel < 0.001 ? stoppedRotVel : rotVel;
        return Math.abs(getVel()) <= v && Math.abs(getRotVel()) <= r;
    }

    /**
     * @param vel    the translational speed {@link #isStopped()} counts as stopped, mm/s
     * @param rotVel the rotational speed it counts as stopped, deg/s
     */
    public void setStoppedVels(double vel, double rotVel) {
        stoppedVel = vel;
        stoppedRotVel = rotVel;
    }

    // ---- the pose's frames and their histories ----

    /**
     * @return the pose the robot's encoders give (the Environment's odometry, re-based by
     *         {@link #setEncoderPose} and {@link #setDeadReconPose}), which {@link #moveTo} does not
     *         change; a new object
     */
    public ArPose getEncoderPose() {
        return frames.encoder(state());
    }

    /** @return the encoder pose's x, mm */
    public double getEncoderX() {
        return getEncoderPose().getX();
    }

    /** @return the encoder pose's y, mm */
    public double getEncoderY() {
        return getEncoderPose().getY();
    }

    /** @return the encoder pose's heading, degrees */
    public double getEncoderTh() {
        return getEncoderPose().getTh();
    }

    /**
     * @return the raw encoder pose: the Environment's odometry before ARIA's encoder correction (of
     *         which RoboSim has none), the same as {@link #getEncoderPose()} until either is set
     */
    public ArPose getRawEncoderPose() {
        return frames.raw(state());
    }

    /**
     * Sets the raw encoder pose, as ARIA's {@code ArRobot::setRawEncoderPose} (ArRobot.h): the robot's
     * motion is added to it from here, and the encoder pose is not changed.
     *
     * @param rawEncoderPose the new raw pose
     */
    public void setRawEncoderPose(ArPose rawEncoderPose) {
        underLock(() -> frames.setRaw(state(), rawEncoderPose));
    }

    /**
     * Sets the encoder pose, as ARIA's {@code ArRobot::setEncoderPose} (ArRobot.h): the robot's motion is
     * added to it from here; the encoder transform is kept, so {@link #getPose()} moves with it.
     *
     * @param encoderPose the new encoder pose
     */
    public void setEncoderPose(ArPose encoderPose) {
        underLock(() -> frames.setEncoder(state(), encoderPose));
    }

    /**
     * ARIA's {@code ArRobot::setDeadReconPose} (ArRobot.cpp): the encoder pose becomes {@code pose} and
     * the encoder transform changes so that {@link #getPose()} stays where it is; the
     * set-encoder-transform callbacks run.
     *
     * @param pose the new encoder (dead-reckoning) pose
     */
    public void setDeadReconPose(ArPose pose) {
        underLock(() -> {
            ArPose global = getPose();
            frames.setEncoder(state(), pose);
            frames.setEncoderTransform(new ArTransform(pose, global));
        });
        events.setEncoderTransform.invoke(getName());
    }

    /** @return the transform from the encoder pose to {@link #getPose()} (the identity until {@link #moveTo}) */
    public ArTransform getEncoderTransform() {
        return frames.encoderTransform();
    }

    /**
     * ARIA's {@code setEncoderTransform(deadReconPos, globalPos)}: {@code deadReconPos} in the encoder
     * frame is {@code globalPos} in the global one; the set-encoder-transform callbacks run. Unlike
     * {@link #moveTo}, the range devices' readings are not moved.
     *
     * @param deadReconPos a pose in the encoder frame
     * @param globalPos    where it is in the global frame
     */
    public void setEncoderTransform(ArPose deadReconPos, ArPose globalPos) {
        setEncoderTransform(new ArTransform(deadReconPos, globalPos));
    }

    /** @param transformPos the global pose of the encoder frame's origin (ARIA's {@code setEncoderTransform(pose)}) */
    public void setEncoderTransform(ArPose transformPos) {
        setEncoderTransform(new ArTransform(new ArPose(0, 0, 0), transformPos));
    }

    /** @param transform the new encoder transform; the set-encoder-transform callbacks run */
    public void setEncoderTransform(ArTransform transform) {
        underLock(() -> frames.setEncoderTransform(transform));
        events.setEncoderTransform.invoke(getName());
    }

    /**
     * @param functor run whenever the encoder transform changes ({@link #moveTo}, {@link
     *     #setEncoderTransform}, {@link #setDeadReconPose})
     */
    public void addSetEncoderTransformCB(Runnable functor) {
        addSetEncoderTransformCB(functor, 50);
    }

    /**
     * @param functor  run whenever the encoder transform changes
     * @param position ARIA's list position: higher runs first (ARIA's {@code ArCallbackList}); here
     *                 every callback is added at the end, in the order added
     */
    public void addSetEncoderTransformCB(Runnable functor, int position) {
        events.setEncoderTransform.add(functor, ArListPos.LAST);
    }

    /** @param functor a set-encoder-transform callback to remove */
    public void remSetEncoderTransformCB(Runnable functor) {
        events.setEncoderTransform.remove(functor);
    }

    /** @return the transform from the robot's frame (x forward) to the global frame, at the robot's pose */
    public ArTransform getToGlobalTransform() {
        return new ArTransform(new ArPose(0, 0, 0), getPose());
    }

    /** @return the transform from the global frame to the robot's frame */
    public ArTransform getToLocalTransform() {
        return new ArTransform(getPose(), new ArPose(0, 0, 0));
    }

    /**
     * @param heading a heading in the robot's frame (the one {@link #moveTo} set), degrees
     * @return the same heading in the encoder frame, in which the Environment turns
     */
    double encoderHeading(double heading) {
        return frames.stateHeading(heading);
    }

    /**
     * Moves the readings of the range devices and the sonar ring by a transform, as ARIA's
     * {@code applyTransform}; the robot's pose is not changed.
     *
     * @param trans        the transform
     * @param doCumulative whether the cumulative buffers move too
     */
    public void applyTransform(ArTransform trans, boolean doCumulative) {
        underLock(() -> {
            rangeDevices.applyTransform(trans, doCumulative);
            sonar.applyTransform(trans);
        });
    }

    /** @param trans the transform, applied to the cumulative buffers too */
    public void applyTransform(ArTransform trans) {
        applyTransform(trans, true);
    }

    /**
     * The global pose at a past (or a little future) simulated time, from the poses of the latest
     * cycles, as ARIA's {@code ArRobot::getPoseInterpPosition} (ArRobot.h; ArInterpolation's answers).
     *
     * @param timeStamp the time
     * @param position  set to the pose, when the answer is 0 or 1
     * @return 1 interpolated, 0 predicted, −1 too far ahead to predict, −2 too old, −3 too few readings
     */
    public int getPoseInterpPosition(ArTime timeStamp, ArPose position) {
        return poseHistory.pose(timeStamp.getTimeMs(), position);
    }

    /** As {@link #getPoseInterpPosition}, for the encoder pose. */
    public int getEncoderPoseInterpPosition(ArTime timeStamp, ArPose position) {
        return encoderPoseHistory.pose(timeStamp.getTimeMs(), position);
    }

    /** @param numReadings how many cycles' global poses {@link #getPoseInterpPosition} keeps (ARIA's 100) */
    public void setPoseInterpNumReadings(int numReadings) {
        poseHistory.setSize(numReadings);
    }

    /** @return how many cycles' global poses are kept */
    public int getPoseInterpNumReadings() {
        return poseHistory.size();
    }

    /** @param numReadings how many cycles' encoder poses {@link #getEncoderPoseInterpPosition} keeps (ARIA's 100) */
    public void setEncoderPoseInterpNumReadings(int numReadings) {
        encoderPoseHistory.setSize(numReadings);
    }

    /** @return how many cycles' encoder poses are kept */
    public int getEncoderPoseInterpNumReadings() {
        return encoderPoseHistory.size();
    }

    /**
     * ARIA's {@code ArRobot::applyEncoderOffset} (ArRobot.cpp): a pose known at one time carried to
     * another by the motion the encoders saw in between (both encoder poses interpolated, then carried
     * into the global frame by the current encoder transform).
     *
     * @param from     the pose
     * @param fromTime when {@code from} held
     * @param to       the time to carry it to
     * @param result   set to {@code from} plus the motion, when the answer is 0 or more
     * @return the answer of the {@code to} interpolation, or the first failing one (below 0)
     */
    public int applyEncoderOffset(ArPose from, ArTime fromTime, ArTime to, ArPose result) {
        ArPose encFrom = new ArPose();
        ArPose encTo = new ArPose();
        int retFrom = getEncoderPoseInterpPosition(fromTime, encFrom);
        if (retFrom < 0) {
            return retFrom;
        }
        int retTo = getEncoderPoseInterpPosition(to, encTo);
        if (retTo < 0) {
            return retTo;
        }
        ArTransform t = getEncoderTransform();
        ArPose a = t.doTransform(encFrom);
        ArPose b = t.doTransform(encTo);
        if (result != null) {
            result.setPose(from.getX() + b.getX() - a.getX(), from.getY() + b.getY() - a.getY(),
                    ArMath.addAngle(from.getTh(), ArMath.subAngle(b.getTh(), a.getTh())));
        }
        return retTo;
    }

    /**
     * @return how many ms the odometry lags the state it comes with (0, ARIA's default): the histories
     *     are stamped that much earlier
     */
    public int getOdometryDelay() {
        return odometryDelayMs;
    }

    /** @param msec how many ms the odometry lags the state it comes with */
    public void setOdometryDelay(int msec) {
        odometryDelayMs = msec;
    }

    /**
     * Re-bases the odometric pose, moving the readings of the range devices with the robot, as ARIA's
     * {@code ArRobot::moveTo(pose)} (with {@code doCumulative} true) does. The robot does not drive:
     * from now on {@link #getPose()} answers {@code pose} plus whatever the encoders add, while
     * {@link #getEncoderPose()} keeps the raw pose. Headings given to {@link ArRobot#setHeading} are in the
     * new frame.
     *
     * @param pose the robot's new pose, mm and degrees
     */
    public void moveTo(ArPose pose) {
        moveTo(pose, true);
    }

    /**
     * As {@link #moveTo(ArPose)}.
     *
     * @param pose         the robot's new pose
     * @param doCumulative whether the range devices' cumulative buffers move too (the current
     *                     buffers and the sonar readings always do)
     */
    public void moveTo(ArPose pose, boolean doCumulative) {
        rebase(new ArTransform(getEncoderPose(), pose), doCumulative);
    }

    /**
     * ARIA's {@code moveTo(poseTo, poseFrom)}: the robot is taken to have been at {@code from} (a pose
     * in the current frame) and to be at {@code to} there; the frame moves by that difference.
     *
     * @param to   where {@code from} is in the new frame
     * @param from a pose in the current frame
     */
    public void moveTo(ArPose to, ArPose from) {
        moveTo(to, from, true);
    }

    /**
     * As {@link #moveTo(ArPose, ArPose)}.
     *
     * @param to           where {@code from} is in the new frame
     * @param from         a pose in the current frame
     * @param doCumulative whether the range devices' cumulative buffers move too
     */
    public void moveTo(ArPose to, ArPose from, boolean doCumulative) {
        rebase(new ArTransform(frames.encoderTransform().doInvTransform(from), to), doCumulative);
    }

    private void rebase(ArTransform newEncoderTransform, boolean doCumulative) {
        lock.lock();
        try {
            ArPose before = getPose();
            frames.setEncoderTransform(newEncoderTransform);
            ArTransform moved = new ArTransform(before, getPose());
            rangeDevices.applyTransform(moved, doCumulative);
            sonar.applyTransform(moved);
        } finally {
            lock.unlock();
        }
        events.setEncoderTransform.invoke(getName());
    }

    // ---- range-device queries ----

    /**
     * The nearest current reading of all the attached range devices in an angle interval (ARIA's
     * {@code checkRangeDevicesCurrentPolar}).
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @return the smallest {@link ArRangeDevice#currentReadingPolar} over the devices (a device with
     *         nothing there answers its maximum range); −1 if no device is attached
     */
    public double checkRangeDevicesCurrentPolar(double startAngle, double endAngle) {
        return checkRangeDevicesCurrentPolar(startAngle, endAngle, null);
    }

    /**
     * As {@link #checkRangeDevicesCurrentPolar(double, double)}, also giving the reading's angle.
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @param angleOut   null, or an array whose element 0 receives the nearest reading's angle
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCurrentPolar(double startAngle, double endAngle, double[] angleOut) {
        return rangeDevices.nearest(d -> d.currentReadingPolar(startAngle, endAngle, null),
                (d, out) -> d.currentReadingPolar(startAngle, endAngle, out), angleOut);
    }

    /**
     * The nearest cumulative reading of all the attached range devices in an angle interval (ARIA's
     * {@code checkRangeDevicesCumulativePolar}).
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @return the smallest {@link ArRangeDevice#cumulativeReadingPolar} over the devices; −1 if no
     *         device is attached
     */
    public double checkRangeDevicesCumulativePolar(double startAngle, double endAngle) {
        return checkRangeDevicesCumulativePolar(startAngle, endAngle, null);
    }

    /**
     * As {@link #checkRangeDevicesCumulativePolar(double, double)}, also giving the reading's angle.
     *
     * @param startAngle degrees, relative to the robot's heading
     * @param endAngle   degrees, relative to the robot's heading
     * @param angleOut   null, or an array whose element 0 receives the nearest reading's angle
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCumulativePolar(double startAngle, double endAngle, double[] angleOut) {
        return rangeDevices.nearest(d -> d.cumulativeReadingPolar(startAngle, endAngle, null),
                (d, out) -> d.cumulativeReadingPolar(startAngle, endAngle, out), angleOut);
    }

    /**
     * The nearest current reading of all the attached range devices in a box around the robot
     * (ARIA's {@code checkRangeDevicesCurrentBox}).
     *
     * @param x1 one corner's x, mm, robot frame (x forward)
     * @param y1 one corner's y, mm, robot frame (y left)
     * @param x2 the opposite corner's x, mm
     * @param y2 the opposite corner's y, mm
     * @return the smallest {@link ArRangeDevice#currentReadingBox} over the devices; −1 if no
     *         device is attached
     */
    public double checkRangeDevicesCurrentBox(double x1, double y1, double x2, double y2) {
        return checkRangeDevicesCurrentBox(x1, y1, x2, y2, null);
    }

    /**
     * As {@link #checkRangeDevicesCurrentBox(double, double, double, double)}, also giving the reading.
     *
     * @param x1         one corner's x, mm, robot frame
     * @param y1         one corner's y, mm, robot frame
     * @param x2         the opposite corner's x, mm
     * @param y2         the opposite corner's y, mm
     * @param readingPos null, or a pose set to the nearest reading in the robot's frame ((0, 0, 0)
     *                   if the nearest device has none in the box, as in ARIA)
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCurrentBox(double x1, double y1, double x2, double y2, ArPose readingPos) {
        return rangeDevices.nearest(d -> d.currentReadingBox(x1, y1, x2, y2, null),
                (d, out) -> d.currentReadingBox(x1, y1, x2, y2, out), readingPos);
    }

    /**
     * The nearest cumulative reading of all the attached range devices in a box around the robot
     * (ARIA's {@code checkRangeDevicesCumulativeBox}).
     *
     * @param x1 one corner's x, mm, robot frame
     * @param y1 one corner's y, mm, robot frame
     * @param x2 the opposite corner's x, mm
     * @param y2 the opposite corner's y, mm
     * @return the smallest {@link ArRangeDevice#cumulativeReadingBox} over the devices; −1 if no
     *         device is attached
     */
    public double checkRangeDevicesCumulativeBox(double x1, double y1, double x2, double y2) {
        return checkRangeDevicesCumulativeBox(x1, y1, x2, y2, null);
    }

    /**
     * As {@link #checkRangeDevicesCumulativeBox(double, double, double, double)}, also giving the
     * reading.
     *
     * @param x1         one corner's x, mm, robot frame
     * @param y1         one corner's y, mm, robot frame
     * @param x2         the opposite corner's x, mm
     * @param y2         the opposite corner's y, mm
     * @param readingPos null, or a pose set to the nearest reading in the robot's frame
     * @return the distance, mm, or −1 if no device is attached
     */
    public double checkRangeDevicesCumulativeBox(double x1, double y1, double x2, double y2, ArPose readingPos) {
        return rangeDevices.nearest(d -> d.cumulativeReadingBox(x1, y1, x2, y2, null),
                (d, out) -> d.cumulativeReadingBox(x1, y1, x2, y2, out), readingPos);
    }
}
