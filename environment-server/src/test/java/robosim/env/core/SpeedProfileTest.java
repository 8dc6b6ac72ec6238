package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** One step of a ramped speed: its end speed and the integral of its trapezoid. */
class SpeedProfileTest {
    @Test
    void aRampThatLastsTheWholeStepCoversItsMeanSpeed() {
        assertEquals(new SpeedProfile(30, 1.5), SpeedProfile.step(0, 300, 300, 300, 0.1));
    }

    @Test
    void aTargetReachedPartWayIsHeldForTheRest() {
        // 20 → 35 at 300 mm/s² takes 0.05 s: 0.05 · 27.5 + 0.05 · 35
        SpeedProfile p = SpeedProfile.step(20, 35, 300, 300, 0.1);
        assertEquals(35, p.speed(), 1e-12);
        assertEquals(0.05 * 27.5 + 0.05 * 35, p.distance(), 1e-12);
    }

    @Test
    void stoppingPartWayCoversVSquaredOverTwoD() {
        SpeedProfile p = SpeedProfile.step(20, 0, 300, 400, 0.1);
        assertEquals(0, p.speed(), 1e-12);
        assertEquals(20 * 20 / 800.0, p.distance(), 1e-12);
    }

    @Test
    void backwardsIsTheMirrorImage() {
        assertEquals(new SpeedProfile(-30, -1.5), SpeedProfile.step(0, -300, 300, 300, 0.1));
    }

    @Test
    void theProfileSpeedEndsTheStepOnTheProfileShortOfTheMark() {
        double v = SpeedProfile.onProfile(10, 60, 200, 300, 300, 0.1, 2200);
        SpeedProfile p = SpeedProfile.step(60, v, 300, 300, 0.1);
        assertTrue(p.distance() <= 10, "covered " + p.distance());
        assertEquals(2 * 200 * (10 - p.distance()), p.speed() * p.speed(), 1e-6, "on the profile, not below it");
    }

    @Test
    void whenEvenBrakingCarriesPastTheMarkItBrakesFully() {
        // 60 mm/s needs 6 mm to stop at 300 mm/s²: with 2 mm to go it cannot stay on the profile
        assertEquals(0, SpeedProfile.onProfile(2, 60, 200, 300, 300, 0.1, 2200));
    }

    @Test
    void farFromTheMarkTheMaximumIsAllowed() {
        assertEquals(500, SpeedProfile.onProfile(10_000, 0, 200, 300, 300, 0.1, 500));
    }
}
