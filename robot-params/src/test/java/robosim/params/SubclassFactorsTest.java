package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** A Pioneer's conversion factors come from the parameter file named after the server's subclass. */
class SubclassFactorsTest {
    @Test
    void theShippedP3dxHasItsDistConvFactorAndAriasDefaultsBesides() {
        ConversionFactors f = RobotParameterFiles.conversionFactorsOfSubclass("p3dx");
        assertEquals(0.485, f.distConvFactor());
        assertEquals(0.001534, f.angleConvFactor());
        assertEquals(20, f.vel2Divisor());
    }

    @Test
    void theShTypesHaveFactorsOfOne() {
        assertEquals(1.0, RobotParameterFiles.conversionFactorsOfSubclass("p3dx-sh").distConvFactor());
    }

    @Test
    void aSubclassWithoutAFileHasAriasDefaults() {
        assertEquals(ConversionFactors.ARIA_DEFAULTS, RobotParameterFiles.conversionFactorsOfSubclass("no-such-robot"));
    }
}
