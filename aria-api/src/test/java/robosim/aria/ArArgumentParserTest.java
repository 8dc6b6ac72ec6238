package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** ARIA's argument parser and the program-wide {@link Aria} calls, as ArArgumentParser.cpp and Aria.cpp behave. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ArArgumentParserTest {
    private final ByteArrayOutputStream log = new ByteArrayOutputStream();

    @BeforeEach
    void captureTheLog() {
        ArLog.setStream(new PrintStream(log, true, StandardCharsets.UTF_8));
    }

    @AfterEach
    void release() {
        ArLog.setStream(null);
    }

    private String log() {
        return log.toString(StandardCharsets.UTF_8);
    }

    /** A program: its parser names it. */
    static final class Program {
        static String name;

        public static void main(String[] args) {
            name = new ArArgumentParser(args).getArg(0);
        }
    }

    @Test
    void argumentZeroIsTheProgramAndFlagsMatchWithoutCaseOrWithASecondHyphen() {
        ArArgumentParser p = new ArArgumentParser(new String[] {"--REMOTEISSIM", "-rla", "left"});
        assertEquals(4, p.getArgc());
        Program.main(new String[0]);
        assertEquals("Program", Program.name, "argument 0 is the main class's name");
        assertTrue(p.checkArgument("-remoteIsSim"));
        assertFalse(p.checkArgument("-remoteIsSim"), "taken once");
        assertTrue(p.checkArgument("-RLA"));
        assertEquals("left", p.getArg(1));
        assertEquals("-rla left", p.getStartingArguments().substring(p.getStartingArguments().indexOf("-rla")));
    }

    @Test
    void aParameterGivenTwiceGivesTheLastAndBothAreTaken() {
        ArArgumentParser p = new ArArgumentParser(new String[] {"-rh", "a", "x", "-rh", "b"});
        String[] host = {"localhost"};
        assertTrue(p.checkParameterArgumentString("-rh", host));
        assertEquals("b", host[0]);
        assertArrayEquals(new String[] {p.getArg(0), "x"}, p.getArgv());
        String[] kept = {"kept"};
        assertTrue(p.checkParameterArgumentString("-absent", kept));
        assertEquals("kept", kept[0], "an absent argument leaves the value");
        ArArgumentParser first = new ArArgumentParser(new String[] {"-n", "1", "-n", "2"});
        assertEquals("1", first.checkParameterArgument("-n", true));
        assertEquals("2", first.checkParameterArgument("-n"));
        assertNull(first.checkParameterArgument("-n"));
    }

    @Test
    void badValuesAreRefusedWithARIAsLines() {
        ArArgumentParser p = new ArArgumentParser(new String[] {"-port", "eighty", "-speed", "fast", "-on", "maybe", "-last"});
        int[] port = {8101};
        assertFalse(p.checkParameterArgumentInteger("-port", port));
        assertEquals(8101, port[0]);
        double[] speed = {1};
        assertFalse(p.checkParameterArgumentDouble("-speed", speed));
        boolean[] on = {false};
        assertFalse(p.checkParameterArgumentBool("-on", on));
        String[] last = {null};
        assertFalse(p.checkParameterArgumentString("-last", last), "given without a value");
        assertEquals(String.join("\n", "Argument given to -port was not an integer it was the string eighty",
                "Argument given to -speed was not a double it was the string fast",
                "Argument given to -on was not a bool (true, false, 1, 0) it was the string maybe",
                "No argument given to -last", ""), log());
        ArArgumentParser good = new ArArgumentParser(new String[] {"-port", "9000", "-speed", "2.5", "-on", "1"});
        boolean[] set = {false};
        assertTrue(good.checkParameterArgumentInteger("-port", port, set, false));
        assertTrue(set[0]);
        assertTrue(good.checkParameterArgumentDouble("-speed", speed));
        assertTrue(good.checkParameterArgumentBool("-on", on));
        assertEquals(9000, port[0]);
        assertEquals(2.5, speed[0]);
        assertTrue(on[0]);
    }

    @Test
    void helpStopsTheProgramAndLeftoversAreLoggedButAllowed() {
        ArArgumentParser help = new ArArgumentParser(new String[] {"/?"});
        assertFalse(help.checkHelpAndWarnUnparsed());
        assertFalse(help.checkHelp(), "help once asked for stays asked for");
        ArArgumentParser rest = new ArArgumentParser(new String[] {"-unknown", "x"});
        assertTrue(rest.checkHelpAndWarnUnparsed());
        assertTrue(log().startsWith("Unhandled arguments to program: -unknown x\nProgram will continue but to see the"
                + " help listing type '"), log());
        assertTrue(new ArArgumentParser(new String[] {"-unknown"}).checkHelpAndWarnUnparsed(1), "one allowed");
    }

    @Test
    void defaultArgumentsComeFirstFromFilesAndKeepQuotedWordsWhole(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("robot.args");
        Files.writeString(file, "-rh \"far host\"\n-rrtp 8102\n");
        ArArgumentParser.addDefaultArgumentFile(file.toString());
        ArArgumentParser p = new ArArgumentParser(new String[] {"-mine"});
        p.loadDefaultArguments();
        assertArrayEquals(new String[] {"-rh", "far host", "-rrtp", "8102", "-mine"},
                List.of(p.getArgv()).subList(1, p.getArgc()).toArray(String[]::new));
        assertTrue(log().contains("Added arguments from file '" + file + "'"), log());
        p.addDefaultArgument("-extra 1", 1);
        assertEquals("-extra", p.getArg(1));
    }

    @Test
    void ariaParsesHighestPositionFirstStopsAtTheFirstFailureAndEachProgramHasItsOwn() throws Exception {
        Aria.init();
        List<String> order = new ArrayList<>();
        Aria.addParseArgsCB(() -> order.add("50"), 50);
        Aria.addParseArgsCB(() -> order.add("75") && false, 75, "robot");
        Aria.addParseArgsCB(() -> order.add("90"), 90);
        assertFalse(Aria.parseArgs());
        assertEquals(List.of("90", "75"), order);
        assertTrue(log().contains("Aria::parseArgs: Failed, parse arg functor 'robot' (75) returned false"), log());
        // another program, as a thread of this JVM, starts its own
        boolean[] theirs = new boolean[1];
        Thread other = new Thread(() -> {
            Aria.init();
            theirs[0] = Aria.parseArgs();
        });
        other.start();
        other.join(10_000);
        assertTrue(theirs[0], "the other program has none of this one's callbacks");
        int[] exited = {-1};
        List<String> exits = new ArrayList<>();
        Aria.addExitCallback(() -> exits.add("low"), 10);
        Aria.addExitCallback(() -> exits.add("high"), 60);
        Aria.setExitHandler(code -> exited[0] = code);
        try {
            Aria.exit(3);
            Aria.exit(4);
        } finally {
            Aria.setExitHandler(null);
        }
        assertEquals(3, exited[0], "a second exit while exiting returns");
        assertEquals(List.of("high", "low"), exits);
        assertFalse(Aria.getRunning());
    }
}
