package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** ARIA's rule for the turn away from pressed bumpers (ArActionBumpers.cpp's findDegreesToTurn). */
class ArActionBumpersTest {
    @Test
    void theMiddleBumperOfFiveTurnsByHalfTheRange() {
        // bumper 2 of 5 stands for 2 · 27 + 13.5 − 67.5 = 0°: turn 67.5 − 0
        assertEquals(67.5, ArActionBumpers.degreesToTurn(1 << 3, 5), 1e-9);
    }

    @Test
    void theRightmostBumperTurnsAShortWayTheOtherWay() {
        // bumper 0 stands for −54°: turn −(67.5 − 54)
        assertEquals(-13.5, ArActionBumpers.degreesToTurn(1 << 1, 5), 1e-9);
    }

    @Test
    void severalPressedBumpersStandForTheMeanOfTheirAngles() {
        // bumpers 3 and 4 stand for 27° and 54°, mean 40.5°: turn 67.5 − 40.5
        assertEquals(27, ArActionBumpers.degreesToTurn((1 << 4) | (1 << 5), 5), 1e-9);
    }
}
