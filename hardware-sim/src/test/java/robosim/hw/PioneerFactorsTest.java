package robosim.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.params.ConversionFactors;
import robosim.params.ParameterFileException;

/** A Pioneer's conversion factors come from the parameter file named after the server's subclass. */
class PioneerFactorsTest {
    @Test
    void theShippedP3dxHasItsDistConvFactorAndAriasDefaultsBesides() {
        ConversionFactors f = PioneerFactors.forSubclass("p3dx");
        assertEquals(0.485, f.distConvFactor());
        assertEquals(0.001534, f.angleConvFactor());
        assertEquals(20, f.vel2Divisor());
    }

    @Test
    void aSubclassWithoutAFileHasAriasDefaults() {
        assertEquals(ConversionFactors.ARIA_DEFAULTS, PioneerFactors.forSubclass("p3dx-sh"));
    }

    @Test
    void aFactorIsReadWhateverItsCase(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("x.p");
        Files.writeString(file, "Section Conversion factors\nrangeconvfactor 0.268 ; old sonar units\n");
        assertEquals(0.268, PioneerFactors.read(file).rangeConvFactor());
    }

    @Test
    void aFactorThatIsNoNumberNamesTheFileAndLine(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("x.p");
        Files.writeString(file, "Class Pioneer\nDistConvFactor abc\n");
        ParameterFileException e = assertThrows(ParameterFileException.class, () -> PioneerFactors.read(file));
        assertTrue(e.getMessage().contains("x.p:2: 'abc' was supplied for DistConvFactor"), e.getMessage());
    }
}
