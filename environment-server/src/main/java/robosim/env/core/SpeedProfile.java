package robosim.env.core;

/**
 * One step of a speed that changes at a bounded rate, as a Pioneer's firmware ramps its wheels: the
 * speed moves towards its target at the acceleration (speeding up) or the deceleration (slowing
 * down or reversing), reaches it part-way through the step if it can, then holds it. The way
 * covered is the integral of that trapezoid, not the end speed times the step, so that speeding up
 * from rest at {@code a} covers a·t²/2 and stopping from {@code v} takes v²/2d, as closed-form
 * kinematics says. The same holds for a rotational speed and the angle it turns.
 *
 * @param speed    the speed at the end of the step
 * @param distance the way covered during the step (mm for mm/s, degrees for deg/s)
 */
record SpeedProfile(double speed, double distance) {
    /**
     * @param current the speed at the start of the step
     * @param target  the speed wanted
     * @param accel   the rate when speeding up, per second, greater than 0
     * @param decel   the rate when slowing down or reversing, per second, greater than 0
     * @param dt      the step, seconds
     * @return the speed at the end of the step and the way covered
     */
    static SpeedProfile step(double current, double target, double accel, double decel, double dt) {
        boolean slowing = Math.abs(target) < Math.abs(current) || Math.signum(target) * Math.signum(current) < 0;
        double rate = slowing ? decel : accel;
        double change = target - current;
        if (change == 0) {
            return new SpeedProfile(target, target * dt);
        }
        double reachedAfter = Math.abs(change) / rate;
        if (reachedAfter >= dt) {
            double end = current + Math.copySign(rate * dt, change);
            return new SpeedProfile(end, (current + end) / 2 * dt);
        }
        return new SpeedProfile(target, (current + target) / 2 * reachedAfter + target * (dt - reachedAfter));
    }

    /**
     * The fastest target speed, up to {@code max}, after whose step the robot is still on a braking
     * profile v = √(2 · {@code profileDecel} · way left): a move or a turn that follows it slows down
     * in time and ends on its mark instead of past it, as the way covered while the speed changes
     * counts in full. Found by bisection, so the same inputs give the same speed.
     *
     * @param way          what is left to go, 0 or more, in the direction of travel
     * @param current      the speed now in the direction of travel (negative when going the other way)
     * @param profileDecel the profile's deceleration, per second, greater than 0
     * @param accel        the rate when speeding up, per second, greater than 0
     * @param decel        the rate when slowing down, per second, greater than 0
     * @param dt           the step, seconds
     * @param max          the highest speed allowed, 0 or more
     * @return the target speed, from 0 to {@code max}; 0 when even braking ends off the profile
     */
    static double onProfile(double way, double current, double profileDecel, double accel, double decel, double dt,
                            double max) {
        if (endsOnProfile(max, way, current, profileDecel, accel, decel, dt)) {
            return max;
        }
        double lo = 0;
        double hi = max;
        for (int i = 0; i < 60 && endsOnProfile(lo, way, current, profileDecel, accel, decel, dt); i++) {
            double mid = (lo + hi) / 2;
            if (endsOnProfile(mid, way, current, profileDecel, accel, decel, dt)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    private static boolean endsOnProfile(double target, double way, double current, double profileDecel,
                                         double accel, double decel, double dt) {
        SpeedProfile p = step(current, target, accel, decel, dt);
        double left = way - p.distance();
        return left >= 0 && p.speed() * p.speed() <= 2 * profileDecel * left;
    }
}
