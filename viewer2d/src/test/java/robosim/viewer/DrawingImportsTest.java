package robosim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The drawing classes stay free of transport, files and logging, so the window, the 3D view and
 * replay can reuse them (docs/DESIGN.md, "Rules the code keeps", rule 3).
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class DrawingImportsTest {
    private static final List<String> FORBIDDEN = List.of(
            "import java.net.", "import java.io.", "import java.nio.", "import javax.imageio.", "import java.util.logging.");

    @ParameterizedTest
    @ValueSource(strings = {"WorldRenderer", "RobotPainter", "LaserPainter", "HeatPainter", "ViewTransform",
        "RenderOptions", "RobotPalette", "ClosedPath"})
    void drawingClassImportsNoTransport(String className) throws IOException {
        Path source = Path.of(System.getProperty("basedir", "."), "src/main/java/robosim/viewer/draw", className + ".java");
        List<String> offending = Files.readAllLines(source).stream()
                .filter(line -> FORBIDDEN.stream().anyMatch(line::startsWith))
                .toList();
        assertEquals(List.of(), offending, className + " must not do I/O");
    }
}
