package robosim.it;

import robosim.cli.Main;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.env.core.RobotSummary;
import robosim.env.net.RunReport;

/**
 * {@code robosim replay} on a recording of a real run (the small maze, 60 steps): the summary,
 * PNG frames of a range, an animated GIF, and damaged recordings.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class ReplayCommandTest {
    private static final int STEPS = 60;

    @TempDir
    static Path shared;

    private static Path recording;
    private static RunReport report;

    @TempDir
    Path dir;

    /** What one execution printed and returned. */
    private record Run(int exit, String out, String err) { }

    @BeforeAll
    static void record() throws Exception {
        recording = shared.resolve("maze.rsr");
        report = RecordedRun.run(STEPS, recording, List.of());
    }

    private static Run execute(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int exit = cl.execute(args);
        return new Run(exit, out.toString(), err.toString());
    }

    private static List<String> files(Path d) throws Exception {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void infoSumsUpTheRunAsTheEnvironmentReportedIt() {
        Run r = execute("replay", recording.toString(), "--info");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().contains("World: small-maze, 8000 x 8000 mm, 100 ms steps"), r.out());
        assertTrue(r.out().contains("Steps: 0 to 60 (61 frames), 6.0 s simulated"), r.out());
        assertTrue(r.out().contains("Ended: done: step limit 60 reached"), r.out());
        for (RobotSummary robot : report.robots()) {
            Matcher m = Pattern.compile("robot " + robot.name() + " \\(pioneer\\): travelled (\\d+) mm, collisions (\\d+)")
                    .matcher(r.out());
            assertTrue(m.find(), r.out());
            assertEquals(robot.distance(), Double.parseDouble(m.group(1)), robot.distance() * 0.01 + 1,
                    "distance from the true poses, as the Environment counted it");
            assertEquals(robot.collisions(), Long.parseLong(m.group(2)));
        }
    }

    @Test
    void pngImagesOfARangeEveryKSteps() throws Exception {
        Path png = dir.resolve("png");
        Run r = execute("replay", recording.toString(), "--png-dir", png.toString(), "--from", "10", "--to", "35",
                "--every", "10", "--width", "300");
        assertEquals(0, r.exit(), r.err());
        assertEquals(List.of("frame-000010.png", "frame-000020.png", "frame-000030.png", "frame-000035.png"), files(png));
        assertEquals(300, ImageIO.read(png.resolve("frame-000020.png").toFile()).getWidth());
        assertTrue(r.out().startsWith("Replay: 4 PNG frames (steps 10 to 35) written to "), r.out());
    }

    @Test
    void threeDimensionalImagesWithTheCameraAndLightGiven() throws Exception {
        Path png = dir.resolve("png3d");
        Run r = execute("replay", recording.toString(), "--png-dir", png.toString(), "--from", "60", "--3d",
                "--azimuth", "-60", "--elevation", "35", "--zoom", "1.5", "--light", "0,45", "--trails");
        assertEquals(0, r.exit(), r.err());
        assertEquals(List.of("frame-000060.png"), files(png));
    }

    @Test
    void anAnimatedGifThatLoopsAtTheStepLength() throws Exception {
        Path gif = dir.resolve("run.gif");
        Run r = execute("replay", recording.toString(), "--gif", gif.toString(), "--every", "10", "--width", "200");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().startsWith("GIF: 7 frames (steps 0 to 60), 1000 ms each, looping"), r.out());
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            assertEquals(7, reader.getNumImages(true));
            reader.dispose();
        }
    }

    @Test
    void aCutShortRecordingReplaysToItsLastStepWithAWarning() throws Exception {
        byte[] bytes = Files.readAllBytes(recording);
        Path cut = dir.resolve("cut.rsr");
        Files.write(cut, java.util.Arrays.copyOf(bytes, bytes.length / 2));
        Path png = dir.resolve("png");
        Run r = execute("replay", cut.toString(), "--png-dir", png.toString(), "--every", "1");
        assertEquals(0, r.exit(), "a run that ended abruptly is still a run: " + r.err());
        Matcher m = Pattern.compile("warning: " + Pattern.quote(cut.toString())
                + ": the recording ends inside the record at byte offset (\\d+) .*, after step (\\d+); steps up to \\2 are readable")
                .matcher(r.err());
        assertTrue(m.find(), r.err());
        int last = Integer.parseInt(m.group(2));
        assertTrue(last > 10 && last < STEPS, r.err());
        assertEquals(last + 1, files(png).size(), "steps 0 to " + last + " drawn");
    }

    @Test
    void aCorruptedRecordingNamesTheOffsetAndStepAndReplaysWhatComesBefore() throws Exception {
        byte[] bytes = Files.readAllBytes(recording);
        bytes[bytes.length / 2] ^= 0x5a;
        Path bad = dir.resolve("bad.rsr");
        Files.write(bad, bytes);
        Path png = dir.resolve("png");
        Run r = execute("replay", bad.toString(), "--png-dir", png.toString(), "--every", "1");
        assertEquals(1, r.exit(), r.err());
        Matcher m = Pattern.compile(Pattern.quote(bad.toString()) + ": bad record at byte offset (\\d+), after step (\\d+): ")
                .matcher(r.err());
        assertTrue(m.find(), r.err());
        assertTrue(Long.parseLong(m.group(1)) <= bytes.length / 2, r.err());
        assertEquals(Integer.parseInt(m.group(2)) + 1, files(png).size(), "every step before the damage drawn");
        assertFalse(r.err().contains("\tat "), "one line, no stack trace");
    }

    @Test
    void usageErrorsExitWith2AndNameTheOption() {
        Run none = execute("replay", recording.toString());
        assertEquals(2, none.exit());
        assertTrue(none.err().contains("Missing required option") && none.err().contains("--png-dir"), none.err());
        Run backwards = execute("replay", recording.toString(), "--info", "--png-dir", dir.toString(), "--from", "5", "--to", "2");
        assertEquals(2, backwards.exit());
        assertEquals(List.of("robosim replay: 2 was supplied for --to: it must be at least --from (5)",
                "Try 'robosim replay --help'."), backwards.err().strip().lines().toList());
        Run light = execute("replay", recording.toString(), "--info", "--light", "east");
        assertEquals(2, light.exit());
        assertTrue(light.err().contains("'east' was supplied for --light"), light.err());
    }

    @Test
    void helpListsTheOutputsAndThe3dOptions() {
        Run r = execute("replay", "--help");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().startsWith("Usage: robosim replay"), r.out());
        for (String option : List.of("--png-dir", "--gif", "--info", "--window", "--from", "--to", "--every", "--3d",
                "--azimuth", "--elevation", "--zoom", "--light", "--trails")) {
            assertTrue(r.out().contains(option), option + " in:\n" + r.out());
        }
        Run viewer = execute("viewer", "--help");
        for (String option : List.of("--record", "--record-sensors", "--window", "--3d")) {
            assertTrue(viewer.out().contains(option), option + " in:\n" + viewer.out());
        }
        assertTrue(execute("env", "--help").out().contains("--record"));
        assertTrue(execute("--help").out().contains("  replay "), "the launcher lists replay");
    }

    @Test
    void aFileThatIsNotARecordingExitsWith1AndSaysSo() throws Exception {
        Path world = LocalEnvironment.root().resolve("testLoadFiles/environment/empty-room.xml");
        Run r = execute("replay", world.toString(), "--info");
        assertEquals(1, r.exit());
        assertEquals("robosim replay: " + world + " is not a RoboSim recording: it starts with \"<?xml ve\", not the magic \"RoboSimR\"",
                r.err().strip());
        Run missing = execute("replay", dir.resolve("none.rsr").toString(), "--info");
        assertEquals(1, missing.exit());
        assertTrue(missing.err().contains("none.rsr is not a file"), missing.err());
    }
}
