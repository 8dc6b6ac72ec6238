package robosim.params;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.protocol.Fuzz;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/**
 * The shipped robot parameter files, in both forms, damaged at random (see {@link Fuzz} to replay a
 * case or run more): numbers swapped for NaN, infinities, huge and malformed ones; keys swapped and
 * lengthened; lines repeated, dropped and replaced by markup, entities and control characters; bytes
 * flipped. Each read gives parameters whose every number is finite, or a
 * {@link ParameterFileException} whose message names the file and a line of it.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ParameterFileFuzzTest {
    private static final Pattern LINE = Pattern.compile("(?:(\\d+): | )");

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"p3dx.p", "scout.p", "p3at.xml", "scout.xml"})
    void aDamagedParameterFileIsReadOrRefusedNamingItsLine(String shipped) throws IOException {
        String valid = Files.readString(ShippedRobots.dir().resolve(shipped));
        Path file = dir.resolve(shipped);
        Fuzz.cases(0x5EED_0301L + shipped.hashCode(), 1000, fuzz -> {
            byte[] bytes = fuzz.random().nextInt(5) == 0 ? fuzz.mutate(valid.getBytes(StandardCharsets.UTF_8))
                    : fuzz.mutateText(valid).getBytes(StandardCharsets.UTF_8);
            Files.write(file, bytes);
            fuzz.input(new String(bytes, StandardCharsets.UTF_8));

            readOrRefused(file, bytes);
        });
    }

    /** @return the line a message names after the file, {@code FILE:LINE: rule}, or 0 for {@code FILE: rule} */
    static int line(Path file, String message) {
        String prefix = file + ":";
        assertTrue(message.startsWith(prefix), "the message names the file: " + message);
        Matcher m = LINE.matcher(message).region(prefix.length(), message.length());
        assertTrue(m.lookingAt(), "a line number or a space follows the file: " + message);
        return m.group(1) == null ? 0 : Integer.parseInt(m.group(1));
    }

    private static void readOrRefused(Path file, byte[] bytes) {
        RobotParameters p;
        try {
            p = RobotParametersReader.read(file);
        } catch (ParameterFileException e) {
            int line = line(file, e.getMessage());
            assertTrue(line <= Fuzz.lines(bytes), "line " + line + " of a file of " + Fuzz.lines(bytes) + " lines: " + e.getMessage());
            return;
        }
        for (double v : List.of(p.robotRadius(), p.robotWidth(), p.robotLengthFront(), p.robotLengthRear(),
                p.maxVelocity(), p.maxRVelocity(), p.transAccel(), p.transDecel(), p.rotAccel(), p.rotDecel(),
                p.diffConvFactor(), p.sonarMaxRange(), p.laserX(), p.laserY(), p.laserTh(), p.laserMaxRange())) {
            assertTrue(Double.isFinite(v), "every number is finite: " + p);
        }
        for (SonarUnit s : p.sonarUnits()) {
            assertTrue(Double.isFinite(s.x()) && Double.isFinite(s.y()) && Double.isFinite(s.th()), "sonar " + s);
        }
    }
}
