package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/** ARIA's priority resolver (ArPriorityResolver.cpp, ArActionDesired.h) on literal desires. */
class ArPriorityResolverTest {
    private static final double EPS = 1e-9;
    private final List<ArResolver.Entry> actions = new ArrayList<>();
    private final ArPriorityResolver resolver = new ArPriorityResolver();

    /** An action that wants what it is told, and keeps the desire it was fired with. */
    private static final class Literal extends ArAction {
        private final Consumer<ArActionDesired> wish;
        private ArActionDesired firedWith;

        Literal(String name, Consumer<ArActionDesired> wish) {
            super(name);
            this.wish = wish;
        }

        @Override
        public ArActionDesired fire(ArActionDesired currentDesired) {
            firedWith = currentDesired;
            ArActionDesired d = new ArActionDesired();
            wish.accept(d);
            return d;
        }
    }

    /** Adds in firing order: call from the highest priority down. */
    private Literal add(int priority, Consumer<ArActionDesired> wish) {
        Literal a = new Literal("p" + priority + "-" + actions.size(), wish);
        actions.add(new ArResolver.Entry(priority, a));
        return a;
    }

    private ArActionDesired resolve() {
        return resolver.resolve(actions, null, false);
    }

    @Test
    void equalPrioritiesAreAveragedByStrength() {
        add(50, d -> d.setVel(100, 0.5));
        add(50, d -> d.setVel(300, 0.25));

        ArActionDesired r = resolve();

        // (100 * 0.5 + 300 * 0.25) / 0.75
        assertEquals(125.0 / 0.75, r.getVel(), EPS);
        assertEquals(0.75, r.getVelStrength(), EPS);
    }

    @Test
    void strengthsSummingPastOneAreCappedAtOneAndTheValueIsStillTheWeightedMean() {
        add(50, d -> d.setVel(100, 0.8));
        add(50, d -> d.setVel(300, 0.6));

        ArActionDesired r = resolve();

        assertEquals((100 * 0.8 + 300 * 0.6) / 1.4, r.getVel(), EPS);
        assertEquals(1.0, r.getVelStrength(), EPS);
    }

    @Test
    void aLowerPriorityGetsOnlyTheStrengthTheHigherLeft() {
        add(80, d -> d.setVel(100, 0.6));
        add(20, d -> d.setVel(400, 1.0));

        ArActionDesired r = resolve();

        // the lower one's strength is cut to 1 - 0.6 = 0.4
        assertEquals(0.6 * 100 + 0.4 * 400, r.getVel(), EPS);
        assertEquals(1.0, r.getVelStrength(), EPS);
    }

    @Test
    void aHigherPriorityAtFullStrengthDecidesAlone() {
        add(80, d -> d.setDeltaHeading(30));
        add(20, d -> d.setDeltaHeading(-90));

        assertEquals(30, resolve().getDeltaHeading(), EPS);
    }

    @Test
    void aLimiterAndAVelocityActionTogether() {
        add(90, d -> d.setMaxVel(150));
        add(10, d -> d.setVel(400));

        ArActionDesired r = resolve();

        // the velocity passes through; its maximum is the limiter's, which the robot applies
        assertEquals(400, r.getVel(), EPS);
        assertEquals(150, r.getMaxVel(), EPS);
        assertEquals(1.0, r.getMaxVelStrength(), EPS);
    }

    @Test
    void acrossPrioritiesTheSlowestMaximumWinsWhateverTheStrength() {
        add(90, d -> d.setMaxVel(300, 0.2));
        add(10, d -> d.setMaxVel(100, 1.0));

        assertEquals(100, resolve().getMaxVel(), EPS);
    }

    @Test
    void withinOnePriorityAMaximumIsTheLastFiredOnesAsInAria() {
        // ARIA's averaging keeps the channel's strength at 0 until the priority ends, so each
        // override value replaces the one before: the action fired last (the one added first) wins
        add(10, d -> d.setMaxVel(100, 1.0));
        add(10, d -> d.setMaxVel(200, 1.0));

        assertEquals(200, resolve().getMaxVel(), EPS);
    }

    @Test
    void aMaximumSetWithoutUseSlowestIsAveraged() {
        add(90, d -> d.setMaxVel(300, 0.5, false));
        add(10, d -> d.setMaxVel(100, 1.0, false));

        assertEquals(0.5 * 300 + 0.5 * 100, resolve().getMaxVel(), EPS);
    }

    @Test
    void theFastestDecelerationAndTheSlowestBackwardSpeedWin() {
        add(90, d -> {
            d.setTransDecel(300);
            d.setMaxNegVel(-400);
        });
        add(10, d -> {
            d.setTransDecel(900);
            d.setMaxNegVel(-100);
        });

        ArActionDesired r = resolve();

        assertEquals(900, r.getTransDecel(), EPS);
        assertEquals(-100, r.getMaxNegVel(), EPS);
    }

    @Test
    void aDeltaHeadingAndARotationalVelocityDoNotMix() {
        add(80, d -> d.setDeltaHeading(30, 0.5));
        add(20, d -> d.setRotVel(20, 1.0));

        ArActionDesired r = resolve();

        assertEquals(30, r.getDeltaHeading(), EPS);
        assertEquals(0, r.getRotVelStrength(), EPS);
    }

    @Test
    void eachActionIsFiredWithWhatTheHigherPrioritiesWant() {
        add(80, d -> d.setVel(250, 0.7));
        Literal low = add(20, d -> { });

        resolve();

        assertEquals(250, low.firedWith.getVel(), EPS);
        assertEquals(0.7, low.firedWith.getVelStrength(), EPS);
    }

    @Test
    void anInactiveActionIsNotFired() {
        add(80, d -> d.setVel(999)).deactivate();
        add(20, d -> d.setVel(100, 0.5));

        ArActionDesired r = resolve();

        assertEquals(100, r.getVel(), EPS);
        assertEquals(0.5, r.getVelStrength(), EPS);
    }

    @Test
    void nothingDesiredGivesNoStrengthAnywhere() {
        add(50, d -> { });

        assertFalse(resolve().isAnythingDesired());
    }

    @Test
    void aStrengthBelowTheMinimumCountsAsNone() {
        add(50, d -> d.setVel(100, ArActionDesired.MIN_STRENGTH / 2));

        assertFalse(resolve().isAnythingDesired());
    }

    @Test
    void anAbsoluteHeadingBecomesADeltaFromTheRobotsHeading() {
        ArActionDesired d = new ArActionDesired();
        d.setHeading(170);

        d.accountForRobotHeading(-170);

        // the short way round: 170 - (-170) = 340, which is -20
        assertEquals(-20, d.getDeltaHeading(), EPS);
        assertTrue(d.isAnythingDesired());
    }

    @Test
    void theSanityCheckRaisesAMaximumBelowZeroAndAnAccelerationBelowOne() {
        ArActionDesired d = new ArActionDesired();
        d.setMaxVel(-50);
        d.setTransAccel(0);
        d.setMaxNegVel(30);

        d.sanityCheck("bad");

        assertEquals(0, d.getMaxVel(), EPS);
        assertEquals(1, d.getTransAccel(), EPS);
        assertEquals(0, d.getMaxNegVel(), EPS);
    }
}
