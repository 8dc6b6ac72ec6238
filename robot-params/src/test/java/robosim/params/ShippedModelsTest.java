package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.protocol.RobotParameters;

/** The models a Pioneer programmer expects are shipped, load without a warning, and carry ARIA's factors. */
class ShippedModelsTest {
    @Test
    void everyShippedFileLoadsWithinTheBoundsAndWithoutAWarning() throws IOException {
        List<Path> files;
        try (Stream<Path> s = Files.list(ShippedRobots.dir())) {
            files = s.filter(p -> p.toString().endsWith(".p") || p.toString().endsWith(".xml")).sorted().toList();
        }
        List<String> warnings = new ArrayList<>();
        Handler handler = new Handler() {
            @Override
            public void publish(LogRecord r) {
                if (r.getLevel().intValue() >= Level.WARNING.intValue()) {
                    warnings.add(r.getMessage());
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger log = Logger.getLogger(ParameterRules.class.getName());
        log.addHandler(handler);
        try {
            for (Path file : files) {
                RobotParameters p = RobotParametersReader.read(file);
                assertNull(p.violation(), file.toString());
            }
        } finally {
            log.removeHandler(handler);
        }
        assertEquals(List.of(), warnings);
        for (String model : List.of("p3dx.p", "p3at.p", "p3dx-sh.p", "p3at-sh.p", "peoplebot.p", "amigo.p", "powerbot.p",
                "p3dx-original.xml")) {
            assertTrue(files.contains(ShippedRobots.dir().resolve(model)), model + " is not among " + files);
        }
    }

    @ParameterizedTest(name = "{0}: {1} sonars, DistConvFactor {2}, VelConvFactor {3}")
    @CsvSource({"p3dx, 16, 0.485, 1.0", "p3at, 16, 0.465, 1.0", "p3dx-sh, 16, 1.0, 1.0", "p3at-sh, 16, 1.0, 1.0",
            "peoplebot, 32, 1.0, 1.0", "amigo, 8, 0.5083, 0.6154", "powerbot, 31, 0.5813, 1.0"})
    void aPioneerModelIsShippedWithItsSonarsAndFactors(String name, int sonars, double dist, double vel) {
        Path root = ShippedRobots.projectRoot();
        String old = System.setProperty("robosim.root", root.toString());
        try {
            assertEquals(sonars, RobotParameterFiles.load(name).sonarUnits().size());
            ConversionFactors f = RobotParameterFiles.conversionFactors(name);
            assertEquals(dist, f.distConvFactor());
            assertEquals(vel, f.velConvFactor());
            assertEquals(0.001534, f.angleConvFactor());
            assertEquals(RobotParameterFiles.load(name).diffConvFactor(), f.diffConvFactor());
        } finally {
            if (old == null) {
                System.clearProperty("robosim.root");
            } else {
                System.setProperty("robosim.root", old);
            }
        }
    }

    @Test
    void anXmlFileHasAriasFactorsWithItsOwnRotationFactor() {
        String old = System.setProperty("robosim.root", ShippedRobots.projectRoot().toString());
        try {
            assertEquals(ConversionFactors.ARIA_DEFAULTS.withDiffConvFactor(0.0034),
                    RobotParameterFiles.conversionFactors("p3at.xml"));
        } finally {
            if (old == null) {
                System.clearProperty("robosim.root");
            } else {
                System.setProperty("robosim.root", old);
            }
        }
    }
}
