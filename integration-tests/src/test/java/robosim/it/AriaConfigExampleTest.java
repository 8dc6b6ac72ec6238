package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.examples.aria.ConfigExample;

/**
 * AriaCoda's {@code configExample.cpp} ported ({@code examples/aria}), run on the shipped {@code
 * configExample.cfg}: what it prints and the file it writes back are what the C++ against libAria
 * prints and writes (but for libAria's "AriaCoda" banner and the example file's path).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AriaConfigExampleTest {
    /** The shipped file as ConfigExample writes it back, the boolean flipped: as libAria writes it. */
    static final String WRITTEN = "ConfigVersion 2.0\n"
            + "Section Example Section\n"
            + "; Contains parameters created by the configExample\n"
            + ";SectionFlags for Example Section: \n"
            + "ExampleIntegerParameter 7 ; range [-10, 10], Example parameter integer.\n\n"
            + "ExampleDoubleParameter 0.25000 ; range [0, 1], Example double precision floating\n"
            + "                         ; point number.\n\n"
            + "ExampleBoolParameter false ; Example boolean parameter.\n\n"
            + "ExampleStringParameter RoboSim's example ; Example string parameter.\n\n";

    @TempDir
    Path dir;

    private Path shipped(String name) throws IOException {
        Path copy = dir.resolve(name);
        Files.copy(LocalEnvironment.root().resolve("examples/aria/configExample.cfg"), copy);
        return copy;
    }

    @Test
    void itLoadsTheFileFlipsTheBoolCallsBackAndWritesTheFileBack() throws IOException {
        Path cfg = shipped("configExample.cfg");
        AriaExamplesTest.Ran ran = AriaExamplesTest.run(ConfigExample::main, cfg.toString());
        assertEquals(0, ran.exit(), ran.out());
        assertEquals("configExample: loading configuration file \"" + cfg + "\"...\n"
                + "configExample: Config changed. New values: int=7, float=0.250000, bool=true, string=\"RoboSim's example\".\n"
                + "configExample: Loaded configuration file \"" + cfg + "\".\n"
                + "configExample: Config changed. New values: int=7, float=0.250000, bool=false, string=\"RoboSim's example\".\n"
                + "configExample: Successfully modified config and invoked callbacks.\n"
                + "configExample: Saving configuration...\n"
                + "configExample: end of program.\n", ran.out());
        assertEquals(WRITTEN, Files.readString(cfg));

        // the written file reads back, with its version, and the bool flips again
        AriaExamplesTest.Ran again = AriaExamplesTest.run(ConfigExample::main, cfg.toString());
        assertEquals(0, again.exit(), again.out());
        assertTrue(again.out().contains("\"...\nArConfig: Config version: 2.0\n"
                + "configExample: Config changed. New values: int=7, float=0.250000, bool=false,"), again.out());
        assertEquals(WRITTEN.replace("ExampleBoolParameter false", "ExampleBoolParameter true"), Files.readString(cfg));
    }

    @Test
    void aValueOutOfBoundsIsRefusedWithAriasLinesAndTheProgramExitsWithoutWriting() throws IOException {
        Path cfg = shipped("bad.cfg");
        String bad = Files.readString(cfg).replace("ExampleIntegerParameter 7 ", "ExampleIntegerParameter 20 ")
                .replace("ExampleDoubleParameter 0.25 ", "ExampleDoubleParameter -2.5 ");
        Files.writeString(cfg, bad);
        AriaExamplesTest.Ran ran = AriaExamplesTest.run(ConfigExample::main, cfg.toString());
        assertEquals(-1, ran.exit(), ran.out());
        assertEquals("configExample: loading configuration file \"" + cfg + "\"...\n"
                + "ArConfigArg of ExampleIntegerParameter: setInt value 20 above range [-10, 10]\n"
                + "ArConfig::parseArgument() error parsing 20\n"
                + "## Last error on line 4 of file '" + cfg + "'\n"
                + "ArConfigArg of ExampleDoubleParameter: setDouble value -2.5 below range [0, 1]\n"
                + "ArConfig::parseArgument() error parsing -2.5\n"
                + "## Last error on line 5 of file '" + cfg + "'\n"
                + "configExample: Config changed. New values: int=0, float=0.500000, bool=true, string=\"RoboSim's example\".\n"
                + "configExample: Error loading configuration file \"" + cfg + "\" . "
                + "Try \"examples/aria/configExample.cfg\".\n", ran.out());
        assertEquals(bad, Files.readString(cfg), "not written");
    }

    @Test
    void aMissingFileIsSaidTheCallbackRunsOnTheDefaultsAndTheProgramExits() {
        Path cfg = dir.resolve("nosuch.cfg");
        AriaExamplesTest.Ran ran = AriaExamplesTest.run(ConfigExample::main, cfg.toString());
        assertEquals(-1, ran.exit(), ran.out());
        assertEquals("configExample: loading configuration file \"" + cfg + "\"...\n"
                + "ArFileParser::parseFile: Could not open file " + cfg + " to parse file.\n"
                + "configExample: Config changed. New values: int=0, float=0.500000, bool=false, string=\"\".\n"
                + "configExample: Error loading configuration file \"" + cfg + "\" . "
                + "Try \"examples/aria/configExample.cfg\".\n", ran.out());
        assertFalse(Files.exists(cfg));
    }

    @Test
    void noArgumentOrHelpGivesTheUsageAndExitsWithOne() {
        String usage = "configExample usage: configExample <config file>.\n"
                + "For example, \"configExample examples/aria/configExample.cfg\".\n";
        AriaExamplesTest.Ran none = AriaExamplesTest.run(ConfigExample::main);
        assertEquals(1, none.exit(), none.out());
        assertEquals(usage, none.out());
        AriaExamplesTest.Ran help = AriaExamplesTest.run(ConfigExample::main, "-help");
        assertEquals(1, help.exit(), help.out());
        assertEquals(usage, help.out());
    }
}
