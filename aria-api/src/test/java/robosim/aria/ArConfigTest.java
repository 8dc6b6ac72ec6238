package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
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

/** ARIA's ArConfig: its file read into a program's fields, written back, and its callbacks. */
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class ArConfigTest {
    @TempDir
    Path dir;

    private final ByteArrayOutputStream log = new ByteArrayOutputStream();
    private ArConfig config;
    private int speed;
    private double ratio = 0.5;
    private boolean on;
    private String label = "";

    @BeforeEach
    void setUp() {
        ArLog.setStream(new PrintStream(log, true, StandardCharsets.UTF_8));
        config = new ArConfig();
        config.setSectionComment("Motion", "How the robot moves");
        config.addParam(ArConfigArg.ofInt("Speed", () -> speed, v -> speed = v, "Speed to go.", -10, 10), "Motion",
                ArPriority.NORMAL);
        config.addParam(ArConfigArg.ofDouble("Ratio", () -> ratio, v -> ratio = v, "A ratio.", 0, 1), "Motion",
                ArPriority.NORMAL);
        config.addParam(ArConfigArg.ofBool("On", () -> on, v -> on = v, "Whether on."), "Motion",
                ArPriority.IMPORTANT);
        config.addParam(ArConfigArg.ofString("Label", () -> label, v -> label = v, "A label.", 8), "Motion",
                ArPriority.TRIVIAL);
    }

    @AfterEach
    void tearDown() {
        ArLog.setStream(null);
    }

    private String file(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p.toString();
    }

    private String log() {
        return log.toString(StandardCharsets.UTF_8);
    }

    @Test
    void aFileSetsTheFieldsWhateverTheCaseOfNamesAndSectionsWithCommentsLeftOut() throws IOException {
        String f = file("a.cfg", "# a comment\nsection motion\nspeed 0x0A ; ten\n  RATIO 1e-1\nOn TRUE # yes\n"
                + "Label  a   b  ; spaces collapse\n");
        assertTrue(config.parseFile(f));
        assertEquals(10, speed);
        assertEquals(0.1, ratio);
        assertTrue(on);
        assertEquals("a b", label);
        assertEquals(f, config.getFileName());
    }

    @Test
    void aValueOutOfBoundsIsRefusedWithAriasLinesAndTheFieldKept() throws IOException {
        String f = file("b.cfg", "Section Motion\nSpeed 20\nRatio -2.5\nOn 1\n");
        assertFalse(config.parseFile(f, true));
        assertEquals(0, speed);
        assertEquals(0.5, ratio);
        assertTrue(on, "continueOnErrors reads on");
        assertEquals("ArConfigArg of Speed: setInt value 20 above range [-10, 10]\n"
                + "ArConfig::parseArgument() error parsing 20\n"
                + "## Last error on line 2 of file '" + f + "'\n"
                + "ArConfigArg of Ratio: setDouble value -2.5 below range [0, 1]\n"
                + "ArConfig::parseArgument() error parsing -2.5\n"
                + "## Last error on line 3 of file '" + f + "'\n", log());
    }

    @Test
    void theFirstErrorEndsTheReadingAndSkipsTheCallbacksUnlessContinuing() throws IOException {
        List<String> called = new ArrayList<>();
        config.addProcessFileCB(() -> called.add("cb"), 0);
        String f = file("c.cfg", "Section Motion\nOn maybe\nSpeed 3\n");
        assertFalse(config.parseFile(f, false));
        assertEquals(0, speed);
        assertEquals(List.of(), called);
        assertTrue(log().startsWith("ArConfig: parameter 'On' is a bool parameter but was given non-bool argument"
                + " of 'maybe'\n"), log());
        assertFalse(config.parseFile(f, true));
        assertEquals(3, speed);
        assertEquals(List.of("cb"), called);
    }

    @Test
    void theSettersSayWhyTheyRefuseInAriasWords() {
        ArConfigArg s = config.findSection("MOTION").findParam("speed");
        StringBuilder error = new StringBuilder("old");
        assertFalse(s.setInt(-11, error, 0, false));
        assertEquals("Speed value of -11 is below minimum of -10.", error.toString());
        assertFalse(s.setInt(11, error, 12, false));
        assertEquals("Speed value", error.toString(), "cut as snprintf cuts to its size");
        assertTrue(s.setInt(-10, error, 0, true));
        assertEquals(0, speed, "doNotSet checks only");
        ArConfigArg r = config.findSection("Motion").findParam("Ratio");
        assertFalse(r.setDouble(1.25, error, 0, false));
        assertEquals("Ratio value of 1.25 is above maximum of 1.", error.toString());
        ArConfigArg l = config.findSection("Motion").findParam("Label");
        assertFalse(l.setString("eight ch", error, 0, false));
        assertEquals("Label string is 8 long when max length is 8.", error.toString());
        assertTrue(l.setString("seven c"));
        assertEquals("seven c", label);
        assertFalse(l.setInt(1), "wrong type");
        assertEquals("range [-10, 10]", s.getBoundsDescr());
        assertEquals("range [0, 1]", r.getBoundsDescr());
    }

    @Test
    void aMissingFileIsLoggedUnlessToldNotToAndTheCallbacksStillRunWhenContinuing() {
        List<String> called = new ArrayList<>();
        config.addProcessFileCB(() -> called.add("cb"), 0);
        String f = dir.resolve("none.cfg").toString();
        assertFalse(config.parseFile(f, true, false, null, 0));
        assertEquals("ArFileParser::parseFile: Could not open file " + f + " to parse file.\n", log());
        assertEquals(List.of("cb"), called);
        log.reset();
        assertFalse(config.parseFile(f, false, true, null, 0));
        assertEquals("", log());
        assertEquals(List.of("cb"), called);
    }

    @Test
    void theFileIsWrittenInAriasFormWithBoundsWrappedCommentsAndKeptUnknowns() throws IOException {
        config.addParam(ArConfigArg.ofDouble("Gain", () -> 2.0, v -> { }, "", 0, Double.POSITIVE_INFINITY, 2), "Tuning");
        config.addSectionFlags("Tuning", "one|two");
        String in = file("d.cfg", "Section Motion\nSpeed -3\nLabel hi\nOdd 1  2\nSection Extra\nAlone\n");
        assertTrue(config.parseFile(in));
        String out = dir.resolve("out.cfg").toString();
        assertTrue(config.writeFile(out));
        assertEquals("ConfigVersion 2.0\n"
                + "Section Motion\n"
                + "; How the robot moves\n"
                + ";SectionFlags for Motion: \n"
                + "Speed -3                 ; range [-10, 10], Speed to go.\n\n"
                + "Ratio 0.50000            ; range [0, 1], A ratio.\n\n"
                + "On false                 ; Whether on.\n\n"
                + "Label hi                 ; A label.\n\n"
                + "Odd 1 2\n\n"
                + "\n"
                + "Section Tuning\n"
                + ";SectionFlags for Tuning: one|two\n"
                + "Gain 2.00                ; minimum 0,\n\n"
                + "\n"
                + "Section Extra\n"
                + ";SectionFlags for Extra: \n"
                + "Alone \n\n", Files.readString(Path.of(out)));
    }

    @Test
    void aLongCommentWrapsAt80ColumnsUnderColumn25() throws IOException {
        ArConfig c = new ArConfig(dir + "/", true, false, false, true);
        int[] v = {7};
        c.addParam(ArConfigArg.ofInt("AParameterWithAVeryLongNameIndeed", () -> v[0], x -> v[0] = x,
                "This description runs on well past the eightieth column, so it goes on the next line."), "S");
        c.addParam(new ArConfigArg("a comment line"), "S");
        c.addParam(new ArConfigArg("NoDescription", 3, ""), "S");
        assertTrue(c.writeFile("w.cfg"));
        // as AriaCoda's libAria writes it, but for the last line, which AriaCoda writes twice on one line
        assertEquals("ConfigVersion 2.0\nSection S\n;SectionFlags for S: \n"
                + "AParameterWithAVeryLongNameIndeed 7 ; This description runs on well past the\n"
                + "                         ; eightieth column, so it goes on the next line.\n"
                + "; a comment line\n"
                + "NoDescription 3\n", Files.readString(dir.resolve("w.cfg")));
    }

    @Test
    void theCallbacksRunHighestPriorityFirstAndTheFirstReasonFillsTheBuffer() {
        List<String> order = new ArrayList<>();
        config.addProcessFileCB(() -> order.add("low"), -5);
        config.addProcessFileCB(() -> order.add("high"), 10);
        config.addProcessFileWithErrorCB(buffer -> {
            order.add("refuses");
            buffer.append("Speed must be even");
            return false;
        }, 0);
        config.addProcessFileCB(() -> order.add("zero, added later"), 0);
        StringBuilder error = new StringBuilder();
        assertFalse(config.callProcessFileCallBacks(true, error, 512));
        assertEquals(List.of("high", "refuses", "zero, added later", "low"), order);
        assertEquals("Speed must be even", error.toString());
        order.clear();
        assertFalse(config.callProcessFileCallBacks(false, error, 512));
        assertEquals(List.of("high", "refuses"), order);
        assertEquals("ArConfig: Failed but continuing, an unnamed process file callback failed\n"
                + "ArConfig: Failed, stopping because unnamed process file callback failed\n", log());
    }

    @Test
    void anUnknownSectionFailsOnlyWhenToldTo() throws IOException {
        ArConfig strict = new ArConfig(null, false, false, true, true);
        strict.addParam(new ArConfigArg("Speed", 1, "", 0, 5), "Motion");
        String f = file("e.cfg", "Section Nowhere\nSpeed 2\nSection Motion\nSpeed 4\n");
        assertFalse(strict.parseFile(f, true));
        assertEquals(4, strict.findSection("Motion").findParam("Speed").getInt());
        assertTrue(log().startsWith("ArConfig: Could not find section 'Nowhere', failing\n"), log());
        assertNull(strict.findSection("Nowhere"));
        assertTrue(config.parseFile(f), "kept as an unknown section by default");
        assertEquals(List.of("Motion", "Nowhere"), config.getSectionNames());
    }

    @Test
    void sectionsGoInOneCategoryEach() {
        assertTrue(config.addSection(ArConfig.CATEGORY_ROBOT_OPERATION, "Motion", "Moving"));
        assertEquals("Moving", config.findSection("Motion").getComment());
        assertTrue(config.addSection(ArConfig.CATEGORY_DEBUG, "Logging", "Logs"));
        assertFalse(config.addSection(ArConfig.CATEGORY_DEBUG, "motion", "again"));
        assertTrue(log().contains("ArConfig: Failed to add section 'motion' to category 'Debug', already defined in"
                + " category 'Robot Operation'\n"), log());
        assertFalse(config.addSection(ArConfig.CATEGORY_DEBUG, "", "nameless"));
        config.setSectionComment("Loose", "in no category");
        assertEquals(List.of("Debug", "Robot Operation"), config.getCategoryNames());
        assertEquals(List.of("Motion"), config.getSectionNamesInCategory(ArConfig.CATEGORY_ROBOT_OPERATION));
        assertEquals(List.of("Loose"), config.getSectionNamesInCategory(""));
    }

    @Test
    void commandLineArgumentsNamingParametersSetThemAndAreTakenOff() {
        ArArgumentParser parser = new ArArgumentParser(new String[] {"-speed", "4", "other", "On", "true"});
        assertTrue(config.parseArgumentParser(parser));
        assertEquals(4, speed);
        assertTrue(on);
        assertEquals(2, parser.getArgc());
        assertEquals("other", parser.getArg(1));
        assertFalse(config.parseArgumentParser(new ArArgumentParser(new String[] {"-Speed", "99"})));
        assertEquals(4, speed);
    }

    @Test
    void eachProgramHasItsOwnConfig() throws Exception {
        Aria.init();
        ArConfig mine = Aria.getConfig();
        assertSame(mine, Aria.getConfig());
        Aria.setDirectory("/some/where");
        assertEquals("/some/where/", mine.getBaseDirectory());
        ArConfig[] other = new ArConfig[1];
        Thread t = new Thread(() -> {
            Aria.init();
            other[0] = Aria.getConfig();
        });
        t.start();
        t.join();
        assertNotSame(mine, other[0]);
        Aria.init();
        assertNotSame(mine, Aria.getConfig(), "init starts afresh");
    }

    @Test
    void prioritiesHaveAriasNamesAndAliases() {
        assertSame(ArPriority.DETAILED, ArPriority.TRIVIAL);
        assertEquals("Advanced", ArPriority.getPriorityName(ArPriority.TRIVIAL));
        assertEquals("Basic", ArPriority.getPriorityName(ArPriority.IMPORTANT));
        boolean[] ok = {false};
        assertSame(ArPriority.EXPERT, ArPriority.getPriorityFromName("expert", ok));
        assertTrue(ok[0]);
        assertSame(ArPriority.LAST_PRIORITY, ArPriority.getPriorityFromName("Nonsense", ok));
        assertFalse(ok[0]);
    }

    @Test
    void cFormatsWriteNumbersAsCsPrintfDoes() {
        assertEquals("1", CFormats.g(1));
        assertEquals("-2.5", CFormats.g(-2.5));
        assertEquals("1e-05", CFormats.g(0.00001));
        assertEquals("100000", CFormats.g(100000));
        assertEquals("1e+06", CFormats.g(999999.5));
        assertEquals("1.23457e+08", CFormats.g(123456789));
        assertEquals("inf", CFormats.g(Double.POSITIVE_INFINITY));
        assertEquals("0.12", CFormats.fixed(0.125, 2));
        assertEquals("-0.00000", CFormats.fixed(-0.000001, 5));
        assertNull(CFormats.parseDouble("1d"));
        assertEquals(Double.NEGATIVE_INFINITY, CFormats.parseDouble("-INF"));
        assertNull(CFormats.parseInt("12abc"));
    }
}
