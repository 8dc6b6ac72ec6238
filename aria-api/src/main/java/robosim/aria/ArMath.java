package robosim.aria;

import java.util.Map;
import java.util.Random;
import java.util.WeakHashMap;
import robosim.hw.AbstractRobot;

/**
 * ARIA's arithmetic for robot programs: angles in degrees, distances, rounding, random numbers. Each
 * rule is ARIA's as {@code ArMath} in ARIA's {@code include/Aria/ariaUtil.h} (AriaCoda) states it;
 * where ARIA's C++ is undefined for a value (NaN, a division by zero) the javadoc says what RoboSim
 * answers.
 *
 * <p><b>Random numbers.</b> ARIA's {@link #random()} is the C library's {@code lrand48()}, which
 * without {@code srand48} repeats the same sequence on every run. RoboSim keeps that determinism and
 * ties it to the run: a thread of a connected robot draws from a generator of its own, seeded from
 * the run's seed ({@link AbstractRobot#getRunSeed()}) and the robot's name, so the same run seed
 * gives each robot the same numbers again, and two robots of one team do not draw the same sequence.
 * A thread outside any connected robot draws from one generator with a fixed seed, as an unseeded
 * {@code lrand48()} would.
 */
public final class ArMath {
    /** ARIA's {@code getRandMax()} on Linux: 2<sup>31</sup>, as ariaUtil.cpp sets it for {@code lrand48}. */
    private static final long RAND_MAX = 2147483648L;
    /** The seed of the generator for threads outside any connected robot. */
    static final long UNSEEDED = 0x1234ABCD330EL; // lrand48's default state, as a reminder of where it comes from
    private static final Random OUTSIDE = new Random(UNSEEDED);
    private static final Map<AbstractRobot, SeededRandom> PER_ROBOT = new WeakHashMap<>();

    /** A robot's generator and the run seed it was made from, so that a new run gets a new one. */
    private record SeededRandom(long runSeed, Random random) { }

    private ArMath() {
    }

    /**
     * As ARIA's {@code ArMath::epsilon} (ariaUtil.h): AriaCoda's is the double's machine epsilon,
     * {@code std::numeric_limits<double>::epsilon()} (ARIA 2.x used 0.00000001).
     *
     * @return 2<sup>-52</sup>, about 2.22e-16
     */
    public static double epsilon() {
        return Math.ulp(1.0);
    }

    /**
     * As ARIA's {@code ArMath::fixAngle360} (ariaUtil.h).
     *
     * @param angle any angle in degrees
     * @return the same direction in [0, 360): 180 stays 180, -90 becomes 270, 360 becomes 0; NaN for
     *         NaN or an infinite angle
     */
    public static double fixAngle360(double angle) {
        if (angle >= 0.0 && angle < 360.0) {
            return angle;
        }
        double a = fixAngle(angle);
        return a >= 0.0 ? a : a + 360.0;
    }

    /**
     * As ARIA's {@code ArMath::cos} (ariaUtil.h): the cosine of an angle in degrees.
     *
     * @param angle degrees
     * @return its cosine
     */
    public static double cos(double angle) {
        return Math.cos(degToRad(angle));
    }

    /**
     * As ARIA's {@code ArMath::sin} (ariaUtil.h): the sine of an angle in degrees.
     *
     * @param angle degrees
     * @return its sine
     */
    public static double sin(double angle) {
        return Math.sin(degToRad(angle));
    }

    /**
     * As ARIA's {@code ArMath::tan} (ariaUtil.h): the tangent of an angle in degrees.
     *
     * @param angle degrees
     * @return its tangent
     */
    public static double tan(double angle) {
        return Math.tan(degToRad(angle));
    }

    /**
     * As ARIA's {@code ArMath::atan2} (ariaUtil.h): the direction of (x, y), in degrees, not
     * normalised further (atan2's own range, [-180, 180]: {@code atan2(-0.0, -1)} is -180).
     *
     * @param y the y distance
     * @param x the x distance
     * @return degrees
     */
    public static double atan2(double y, double x) {
        return radToDeg(Math.atan2(y, x));
    }

    /**
     * As ARIA's {@code ArMath::fabs} (ariaUtil.h).
     *
     * @param val a number
     * @return its absolute value
     */
    public static double fabs(double val) {
        return val < 0.0 ? -val : val;
    }

    /**
     * As ARIA's {@code ArMath::fixAngle} (ariaUtil.h).
     *
     * @param angle any angle in degrees
     * @return the same direction in (-180, 180]: 180 stays 180, -180 becomes 180, 540 becomes 180;
     *         NaN for NaN or an infinite angle (ARIA's integer arithmetic is undefined there)
     */
    public static double fixAngle(double angle) {
        if (angle > -180.0 && angle <= 180.0) {
            return angle; // what the remainder gives here too, without its cost (every pose passes here)
        }
        double a = Math.IEEEremainder(angle, 360.0);
        return a <= -180.0 ? a + 360.0 : a;
    }

    /**
     * @param ang1 degrees
     * @param ang2 degrees
     * @return {@code fixAngle(ang1 + ang2)}, in (-180, 180]
     */
    public static double addAngle(double ang1, double ang2) {
        return fixAngle(ang1 + ang2);
    }

    /**
     * @param ang1 degrees
     * @param ang2 degrees
     * @return {@code fixAngle(ang1 - ang2)}
     */
    public static double subAngle(double ang1, double ang2) {
        return fixAngle(ang1 - ang2);
    }

    /**
     * ARIA's interval rule for robot-relative angles: with start &lt; end, strictly between them;
     * with start &gt; end, the interval wraps through 180°; equal bounds match nothing.
     *
     * @param th    the angle tested, degrees
     * @param start the interval's start, degrees (normalised here)
     * @param end   the interval's end, degrees (normalised here)
     * @return whether {@code th} lies strictly inside
     */
    public static boolean angleBetween(double th, double start, double end) {
        double s = fixAngle(start);
        double e = fixAngle(end);
        double t = fixAngle(th);
        if (s < e) {
            return t > s && t < e;
        }
        if (s > e) {
            return t > s || t < e;
        }
        return false;
    }

    /**
     * @param deg an angle in degrees
     * @return the angle in radians
     */
    public static double degToRad(double deg) {
        return deg * Math.PI / 180.0;
    }

    /**
     * @param rad an angle in radians
     * @return the angle in degrees
     */
    public static double radToDeg(double rad) {
        return rad * 180.0 / Math.PI;
    }

    /**
     * @param x1 the first point's x
     * @param y1 the first point's y
     * @param x2 the second point's x
     * @param y2 the second point's y
     * @return the straight-line distance between the two points
     */
    public static double distanceBetween(double x1, double y1, double x2, double y2) {
        return Math.hypot(x1 - x2, y1 - y2);
    }

    /**
     * ARIA's rounding: 0.49 is added and the result floored, so that a value just under one half
     * goes down and one half itself goes down too ({@code roundInt(2.5)} is 2, {@code roundInt(-2.5)}
     * is -3, {@code roundInt(0.51)} is 1); the result is held within an int's range. Programs that
     * turn readings into whole millimetres rely on this rule.
     *
     * @param val a value
     * @return the int ARIA rounds it to; 0 for NaN
     */
    public static int roundInt(double val) {
        double v = Math.floor(val + 0.49);
        if (Double.isNaN(v)) {
            return 0;
        }
        return v >= Integer.MAX_VALUE ? Integer.MAX_VALUE : v <= Integer.MIN_VALUE ? Integer.MIN_VALUE : (int) v;
    }

    /**
     * As ARIA's {@code ArMath::roundShort} (ariaUtil.h): {@link #roundInt}'s rule (add 0.49, floor)
     * held within a short's range.
     *
     * @param val a value
     * @return the short ARIA rounds it to, -32768 to 32767; 0 for NaN
     */
    public static short roundShort(double val) {
        double v = Math.floor(val + 0.49);
        if (Double.isNaN(v)) {
            return 0;
        }
        return v >= Short.MAX_VALUE ? Short.MAX_VALUE : v <= Short.MIN_VALUE ? Short.MIN_VALUE : (short) v;
    }

    /**
     * As ARIA's {@code ArMath::pointRotate(double *x, double *y, double th)} (ariaUtil.h), with the
     * point in an array: rotates the point about the origin by {@code -th}, as ARIA's does
     * ({@code x' = cos·x + sin·y}, {@code y' = cos·y − sin·x}): the point's coordinates in a frame
     * turned by {@code th}.
     *
     * @param xy the point, {x, y}, changed in place
     * @param th degrees
     * @throws IllegalArgumentException if {@code xy} does not have two elements
     */
    public static void pointRotate(double[] xy, double th) {
        if (xy == null || xy.length != 2) {
            throw new IllegalArgumentException("pointRotate needs the point as an array {x, y}");
        }
        double cs = cos(th);
        double sn = sin(th);
        double x = xy[0];
        double y = xy[1];
        xy[0] = cs * x + sn * y;
        xy[1] = cs * y - sn * x;
    }

    /**
     * As ARIA's {@code ArMath::random} (ariaUtil.h, {@code lrand48} on Linux): a number from 0 to
     * {@link #getRandMax()} − 1, from the calling robot's seeded generator (see the class comment).
     *
     * @return 0 to 2<sup>31</sup> − 1
     */
    public static long random() {
        return generator().nextInt() & 0x7fffffffL;
    }

    /**
     * As ARIA's {@code ArMath::getRandMax} (ariaUtil.cpp sets 2<sup>31</sup> for Linux's
     * {@code lrand48}); {@link #random()} stays below it.
     *
     * @return 2147483648
     */
    public static long getRandMax() {
        return RAND_MAX;
    }

    /**
     * As ARIA's {@code ArMath::randomInRange} (ariaUtil.cpp): {@code m + random() % (n − m)}, so from
     * {@code m} up to but not including {@code n}. With {@code n < m} ARIA's arithmetic is kept (the
     * remainder of a negative divisor is not negative: from {@code m} up to {@code 2m − n}).
     *
     * @param m the lowest value
     * @param n one more than the highest value
     * @return the number drawn
     * @throws IllegalArgumentException if {@code n == m} (ARIA divides by zero there)
     */
    public static long randomInRange(long m, long n) {
        if (n == m) {
            throw new IllegalArgumentException("randomInRange(" + m + ", " + n
                    + "): the range is empty (ARIA divides by n - m, which is 0)");
        }
        return m + random() % (n - m);
    }

    /** @return the generator the calling thread draws from (see the class comment) */
    private static Random generator() {
        return generatorFor(AbstractRobot.current());
    }

    /**
     * @param robot the robot whose thread draws, or null
     * @return its generator, made for its run's seed on first use; the fixed-seed one for null or a
     *         robot not connected
     */
    static Random generatorFor(AbstractRobot robot) {
        if (robot == null || !robot.isConnected()) {
            return OUTSIDE;
        }
        synchronized (PER_ROBOT) {
            long seed = robot.getRunSeed();
            SeededRandom r = PER_ROBOT.get(robot);
            if (r == null || r.runSeed() != seed) {
                r = new SeededRandom(seed, new Random(robotSeed(seed, robot.getName())));
                PER_ROBOT.put(robot, r);
            }
            return r.random();
        }
    }

    /**
     * @param runSeed the run's seed
     * @param name    the robot's name
     * @return the seed of that robot's generator in that run
     */
    static long robotSeed(long runSeed, String name) {
        long h = runSeed * 0x9E3779B97F4A7C15L + name.hashCode();
        h ^= h >>> 33;
        h *= 0xff51afd7ed558ccdL;
        return h ^ (h >>> 33);
    }

    /**
     * As ARIA's {@code ArMath::squaredDistanceBetween} (ariaUtil.h).
     *
     * @param x1 the first point's x
     * @param y1 the first point's y
     * @param x2 the second point's x
     * @param y2 the second point's y
     * @return the squared distance between the two points
     */
    public static double squaredDistanceBetween(double x1, double y1, double x2, double y2) {
        return (x1 - x2) * (x1 - x2) + (y1 - y2) * (y1 - y2);
    }

    /**
     * As ARIA's {@code ArMath::log2} (ariaUtil.h), which divides {@code log10(x)} by 0.3010303, a
     * rounded log10(2): so {@code log2(8)} is 2.9999990..., not 3, and a program that truncates it
     * gets 2, as under ARIA.
     *
     * @param x a positive number
     * @return ARIA's base-2 logarithm; NaN for a negative x, -infinity for 0
     */
    public static double log2(double x) {
        return Math.log10(x) / 0.3010303;
    }

    /**
     * As ARIA's {@code ArMath::isNan} (ariaUtil.h).
     *
     * @param d a number
     * @return whether it is NaN
     */
    public static boolean isNan(double d) {
        return Double.isNaN(d);
    }

    /**
     * As ARIA's {@code ArMath::isFinite} (ariaUtil.h).
     *
     * @param d a number
     * @return whether it is neither NaN nor infinite
     */
    public static boolean isFinite(double d) {
        return Double.isFinite(d);
    }

    /**
     * As ARIA's {@code ArMath::compareFloats(f1, f2, epsilon)} (ariaUtil.h).
     *
     * @param f1      a number
     * @param f2      another
     * @param epsilon how far apart they may be
     * @return whether {@code |f2 − f1| <= epsilon} (or is below the smallest normal double); false if
     *         either is NaN
     */
    public static boolean compareFloats(double f1, double f2, double epsilon) {
        double d = fabs(f2 - f1);
        return d <= epsilon || d < Double.MIN_NORMAL;
    }

    /**
     * As ARIA's {@code ArMath::compareFloats(f1, f2)} (ariaUtil.h): within {@link #epsilon()}.
     *
     * @param f1 a number
     * @param f2 another
     * @return whether they are equal but for floating-point error of at most {@link #epsilon()}
     */
    public static boolean compareFloats(double f1, double f2) {
        return compareFloats(f1, f2, epsilon());
    }
}
