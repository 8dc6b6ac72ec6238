package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import robosim.protocol.RobotParameters;

/**
 * A local check against ARIA's own robot parameter files: every one of them loads, within the
 * Environment's bounds. It needs a copy of ARIA (AriaCoda): its {@code params} folder is the
 * system property {@code robosim.aria.params}, else {@code $ARIA/params} (ARIA's own environment
 * variable for where it is), else ARIA's default install, {@code /usr/local/Aria/params}. Without
 * one it is skipped and says so. The project's own tests do not depend on it: the ARIA-format
 * fixtures in {@link AriaFormatTest} cover the same features.
 */
class AriaParameterFilesTest {
    private static final Path PARAMS = Path.of(System.getProperty("robosim.aria.params",
            System.getenv("ARIA") != null ? Path.of(System.getenv("ARIA"), "params").toString() : "/usr/local/Aria/params"));

    @Test
    void everyAriaParameterFileLoads() throws IOException {
        Assumptions.assumeTrue(Files.isDirectory(PARAMS),
                "skipped: no ARIA params folder at " + PARAMS + " (set ARIA=<AriaCoda folder> or -Drobosim.aria.params=...)");
        List<Path> files;
        try (Stream<Path> s = Files.list(PARAMS)) {
            files = s.filter(p -> p.toString().endsWith(".p")).sorted().toList();
        }
        List<String> failures = new ArrayList<>();
        for (Path file : files) {
            try {
                RobotParameters p = ParameterFileReader.read(file);
                String bad = p.violation();
                if (bad != null) {
                    failures.add(file + ": " + bad);
                }
                ParameterFileReader.conversionFactors(file);
            } catch (RuntimeException e) {
                failures.add(e.getMessage());
            }
        }
        assertTrue(files.size() >= 48, "expected ARIA's 48 files, found " + files.size());
        assertEquals(List.of(), failures);
    }

    @Test
    void aSonarBoardsRangeDoesNotBecomeTheRingsRange() {
        Path p3dx = PARAMS.resolve("p3dx-sh.p");
        Assumptions.assumeTrue(Files.isRegularFile(p3dx), "skipped: no ARIA file at " + p3dx);
        RobotParameters p = ParameterFileReader.read(p3dx);
        assertEquals(5000, p.sonarMaxRange());
        assertEquals(16, p.sonarUnits().size());
        assertNull(p.violation());
    }
}
