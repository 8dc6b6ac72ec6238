package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import robosim.env.world.RobotSpec;
import robosim.params.RobotParameterFiles;

class PioneerOptionsTest {
    private static RobotSpec robot(String file) {
        Path p = RobotParameterFiles.resolve(file);
        return new RobotSpec("r1", "pioneer", 0, 0, 0, p, RobotParameterFiles.load(file), 1);
    }

    @Test
    void anAriaFileGivesItsOwnFactors() {
        assertEquals(0.485, PioneerOptions.factors(robot("p3dx.p")).distConvFactor());
        assertEquals(0.465, PioneerOptions.factors(robot("p3at.p")).distConvFactor());
    }

    @Test
    void anXmlFileGetsTheFactorsOfItsSubclassesAriaModel() {
        assertEquals(0.485, PioneerOptions.factors(robot("p3dx.xml")).distConvFactor());
    }

    @Test
    void aModelWithoutAnAriaFileGetsAriasDefaults() {
        assertEquals(1.0, PioneerOptions.factors(robot("scout.xml")).distConvFactor());
    }
}
