package robosim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.experiment.RunSpec.Link;
import robosim.experiment.RunSpec.MazePlan;

/** The experiment file: what it gives each run, and its errors, each with the file, line and rule. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ExperimentReaderTest {
    @TempDir
    Path dir;

    private static final String GOOD = """
            name: teams
            world:
              maze:
                cells: [6, 4]
                cellSize: 1600
            programs:
              - class: robosim.examples.goldfinder.GoldFinder
                count: ${team}
                args: ["--tag=${team}-${seed}"]
            comms:
              loss: ${loss}
              latency: 2
            factors:
              team: [1, 4]
              loss: [0, 0.25]
            replicates: 3
            firstSeed: 10
            steps: 5000
            """;

    private Path write(String text) throws Exception {
        Path f = dir.resolve("e.yaml");
        Files.writeString(f, text, StandardCharsets.UTF_8);
        return f;
    }

    private ExperimentFileException error(String text) throws Exception {
        Path f = write(text);
        return assertThrows(ExperimentFileException.class, () -> ExperimentReader.read(f));
    }

    @Test
    void theGridGivesEveryCombinationTheLastFactorFastestEachWithItsReplicates() throws Exception {
        Experiment e = ExperimentReader.read(write(GOOD));
        assertEquals("teams", e.name());
        assertEquals(List.of("team", "loss"), e.factorNames());
        assertEquals(List.of(Map.of("team", "1", "loss", "0"), Map.of("team", "1", "loss", "0.25"),
                Map.of("team", "4", "loss", "0"), Map.of("team", "4", "loss", "0.25")), e.combinations());
        assertEquals(12, e.runCount());
        RunSpec r = e.run(7);   // the third combination's second replicate
        assertEquals(Map.of("team", "4", "loss", "0"), r.factors());
        assertEquals(2, r.replicate());
        assertEquals(11, r.seed(), "seeds are firstSeed + replicate - 1, the same for every combination");
        assertEquals(new MazePlan(6, 4, 1600, 11, "p3dx", Map.of()), r.world(), "the maze's seed is the run's");
        assertEquals(4, r.programs().get(0).count());
        assertEquals(List.of("--tag=4-11"), r.programs().get(0).args());
        assertEquals(Link.IN_PROCESS, r.programs().get(0).link());
        assertEquals(0.0, r.comms().loss());
        assertEquals(2, r.comms().latency());
        assertEquals(null, r.comms().range(), "what the file leaves out stays the world's");
        assertEquals(5000, r.steps());
        assertEquals("team", e.plotX(), "the plots put the first factor along x unless told");
    }

    @Test
    void casesListTheCombinationsOneByOne() throws Exception {
        Experiment e = ExperimentReader.read(write(GOOD.replace("""
                factors:
                  team: [1, 4]
                  loss: [0, 0.25]
                """, """
                cases:
                  - {team: 1, loss: 0}
                  - {team: 8, loss: 0.5}
                """)));
        assertEquals(List.of(Map.of("team", "1", "loss", "0"), Map.of("team", "8", "loss", "0.5")), e.combinations());
        assertEquals(6, e.runCount());
    }

    @Test
    void aValueAFactorFillsInIsCheckedForEveryRunBeforeAnyRuns() throws Exception {
        ExperimentFileException x = error(GOOD.replace("loss: [0, 0.25]", "loss: [0, 1.5]"));
        assertEquals(11, x.line(), "the line of the value it fills: " + x.getMessage());
        assertTrue(x.getMessage().contains("1.5 is given for comms.loss: it must be from 0 to 1 in run 3 (team=1, loss=1.5)"),
                x.getMessage());
        assertTrue(x.getMessage().startsWith(dir.resolve("e.yaml") + " line 11: "), x.getMessage());
    }

    @Test
    void eachRuleIsToldWithItsLine() throws Exception {
        assertEquals(4, error(GOOD.replace("    cells: [6, 4]", "    cell: [6, 4]")).line(),
                "an unknown key");
        ExperimentFileException twice = error(GOOD.replace("replicates: 3", "replicates: 3\nreplicates: 4"));
        assertEquals(17, twice.line());
        assertTrue(twice.getMessage().contains("given twice in one mapping (first on line 16)"), twice.getMessage());
        ExperimentFileException unknown = error(GOOD.replace("count: ${team}", "count: ${teams}"));
        assertEquals(8, unknown.line());
        assertTrue(unknown.getMessage().contains("uses ${teams}, but there is no factor teams"), unknown.getMessage());
        assertEquals(8, error(GOOD.replace("count: ${team}", "count: many")).line(), "a count that is no number");
        ExperimentFileException both = error(GOOD + "cases:\n  - {team: 1, loss: 0}\n");
        assertTrue(both.getMessage().contains("factors and cases are both given"), both.getMessage());
        ExperimentFileException steps = error(GOOD.replace("steps: 5000\n", ""));
        assertTrue(steps.getMessage().contains("steps is missing"), steps.getMessage());
        ExperimentFileException world = error(GOOD.replace("world:\n", "world:\n  file: w.xml\n"));
        assertEquals(2, world.line());
        assertTrue(world.getMessage().contains("world gives both file and maze"), world.getMessage());
        ExperimentFileException yaml = error("name: [unclosed\nsteps: 3\n");
        assertTrue(yaml.getMessage().contains("not well-formed YAML"), yaml.getMessage());
        ExperimentFileException builtIn = error(GOOD.replace("  team: [1, 4]", "  seed: [1, 4]"));
        assertTrue(builtIn.getMessage().contains("every run fills in ${seed} itself"), builtIn.getMessage());
        ExperimentFileException link = error(GOOD.replace("    count: ${team}\n", "    count: ${team}\n    link: tcp\n"));
        assertEquals(9, link.line());
        assertTrue(link.getMessage().contains("it is in-process (threads of the run's JVM) or jvm"), link.getMessage());
        ExperimentFileException plot = error(GOOD + "plot:\n  x: speed\n");
        assertTrue(plot.getMessage().contains("plot.x is 'speed': it names one of the factors (team, loss)"),
                plot.getMessage());
        ExperimentFileException name = error(GOOD.replace("name: teams", "name: \"x\\ntouch PWNED\""));
        assertEquals(1, name.line());
        assertTrue(name.getMessage().contains("it names its folder and its cluster job"), name.getMessage());
        ExperimentFileException reserved = error(GOOD.replace("  team: [1, 4]", "  robots: [1, 4]")
                .replace("${team}", "${robots}"));
        assertTrue(reserved.getMessage().contains("results.csv or summary.csv has a column of that name"),
                reserved.getMessage());
        ExperimentFileException emptyCase = error(GOOD.replace("""
                factors:
                  team: [1, 4]
                  loss: [0, 0.25]
                """, """
                cases:
                  - {}
                  - {team: 1, loss: 0}
                """));
        assertTrue(emptyCase.getMessage().contains("an empty case"), emptyCase.getMessage());
        ExperimentFileException noCount = error(GOOD.replace("    count: ${team}\n", ""));
        assertTrue(noCount.getMessage().contains("give every program a count"), noCount.getMessage());
        ExperimentFileException floaty = error(GOOD.replace("latency: 2", "range: 0.25f"));
        assertTrue(floaty.getMessage().contains("'0.25f' is given for comms.range: it must be a number"),
                floaty.getMessage());
        ExperimentFileException two = error(GOOD + "---\nname: again\n");
        assertTrue(two.getMessage().contains("a second YAML document"), two.getMessage());
        ExperimentFileException robotFile = error(GOOD.replace("cellSize: 1600", "cellSize: 1600\n    robotFile: p9x"));
        assertEquals(6, robotFile.line());
        assertTrue(robotFile.getMessage().contains("robot parameter file 'p9x' not found"), robotFile.getMessage());
        ExperimentFileException property = error(GOOD.replace("world:\n", "world:\n  properties: {2fast: x}\n"));
        assertEquals(3, property.line());
        assertTrue(property.getMessage().contains("'2fast' is a world property's name"), property.getMessage());
        ExperimentFileException empty = error("");
        assertTrue(empty.getMessage().contains("the file is empty"), empty.getMessage());
    }

    @Test
    void theFingerprintIsOfTheRunsNotOfThePlotsTheNameOrTheComments() throws Exception {
        String runs = ExperimentFiles.fingerprint(ExperimentReader.read(write(GOOD)));
        assertEquals(runs, ExperimentFiles.fingerprint(ExperimentReader.read(write("# a comment\n"
                + GOOD.replace("name: teams", "name: other") + "metrics: [steps]\nplot: {x: loss, metrics: [steps]}\n"))));
        assertTrue(!runs.equals(ExperimentFiles.fingerprint(ExperimentReader.read(write(GOOD.replace("steps: 5000",
                "steps: 5001"))))), "another step limit, other runs");
        assertTrue(!runs.equals(ExperimentFiles.fingerprint(ExperimentReader.read(write(GOOD.replace("[0, 0.25]",
                "[0, 0.5]"))))), "another factor value, other runs");
    }

    @Test
    void aWorldFileIsFoundBesideTheExperimentFile() throws Exception {
        Path root = robosim.params.RobotParameterFiles.root();
        Files.createDirectories(dir.resolve("worlds"));
        Files.writeString(dir.resolve("worlds/arena.xml"), Files.readString(root.resolve(
                "testLoadFiles/environment/small-maze.xml")).replace("../robots/p3dx.p",
                root.resolve("testLoadFiles/robots/p3dx.p").toString()));
        ExperimentFileException missing = error("""
                world:
                  file: worlds/none.xml
                programs: [{class: a.B}]
                steps: 100
                """);
        assertEquals(2, missing.line());
        assertTrue(missing.getMessage().contains("none.xml, which does not exist"), missing.getMessage());
        Experiment e = ExperimentReader.read(write("""
                world:
                  file: worlds/arena.xml
                  properties: {goal: "${side}"}
                programs:
                  - {class: a.B, link: jvm}
                factors:
                  side: [left, right]
                steps: 100
                """));
        RunSpec r = e.run(1);
        assertEquals(new RunSpec.FilePlan(dir.resolve("worlds/arena.xml"), Map.of("goal", "right")), r.world());
        assertEquals(-1, r.programs().get(0).count(), "no count: the world's robots");
        assertEquals(Link.JVM, r.programs().get(0).link());
        assertEquals("e", e.name(), "the file's name without .yaml");
    }
}
