package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import robosim.cli.Main;
import robosim.env.core.RobotSummary;
import robosim.env.net.Departure;
import robosim.env.net.RunReport;
import robosim.env.net.ServerOptions;
import robosim.env.world.RobotToPlace;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;

/**
 * The README's tour: its first program, taken from the README, saved in a folder outside the clone,
 * compiled there against the classpath {@code robosim classpath} prints, and run there with plain
 * {@code java} (no {@code robosim.root}: the program finds {@code p3dx} from the jars' clone) as
 * robot {@code r1} of the shipped {@code office.map}.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class RobotOutsideTheCloneTest {
    @TempDir
    Path mine;

    @Test
    void theTourProgramCompilesAndRunsFromAFolderOfItsOwnAgainstThePrintedClasspath() throws Exception {
        Path root = LocalEnvironment.root();
        assumeTrue(Files.isDirectory(root.resolve("launcher/target/lib")),
                "launcher/target/lib is made by the launcher's package phase (mvn verify, or bin/robosim): not built yet");
        assertFalse(mine.toAbsolutePath().startsWith(root), mine + " lies outside the clone " + root);
        String classpath = printedClasspath();
        for (String entry : classpath.split(File.pathSeparator)) {
            assertTrue(Path.of(entry).isAbsolute() && Files.isRegularFile(Path.of(entry)), entry);
        }

        Path source = Files.writeString(mine.resolve("Square.java"), firstJavaProgram(root.resolve("README.md")));
        ByteArrayOutputStream javac = new ByteArrayOutputStream();
        int compiled = ToolProvider.getSystemJavaCompiler().run(null, javac, javac, "-cp", classpath, "-d",
                mine.resolve("out").toString(), source.toString());
        assertEquals(0, compiled, () -> "javac -cp \"$(bin/robosim classpath)\" -d out Square.java:\n" + javac);
        assertTrue(Files.isRegularFile(mine.resolve("out/Square.class")), javac::toString);

        World office = WorldReader.read(root.resolve("testLoadFiles/environment/office.map"),
                List.of(new RobotToPlace("p3dx", "r1")));
        try (LocalEnvironment env = new LocalEnvironment(office, 1, ServerOptions.loopback().withMaxSteps(2000))) {
            Path log = mine.resolve("square.log");
            ProcessBuilder pb = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", classpath + File.pathSeparator + "out", "Square", "r1", "127.0.0.1",
                    Integer.toString(env.robotPort()))
                    .directory(mine.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
            pb.environment().remove("ROBOSIM_JAVA_OPTS");
            Process p = pb.start();
            try {
                assertTrue(p.waitFor(90, TimeUnit.SECONDS), "the program ended within 90 s");
            } finally {
                p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
            String out = Files.readString(log);
            assertEquals(0, p.exitValue(), out);
            assertEquals(4, out.lines().filter(l -> l.startsWith("pose ") && l.contains("front sonar")).count(), out);
            RunReport report = env.await(60);
            RobotSummary r1 = report.robots().get(0);
            assertEquals("r1", r1.name());
            assertEquals(4000, r1.distance(), 100, "four sides of 1 m");
            assertEquals(0, r1.collisions());
            assertEquals(Departure.Kind.LEFT, report.departure("r1").orElseThrow().kind());
        }
    }

    /** @return what {@code robosim classpath} prints, run as bin/robosim runs it, under the clone's root */
    private static String printedClasspath() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        String old = System.setProperty("robosim.root", LocalEnvironment.root().toString());
        try {
            assertEquals(0, cl.execute("classpath"), err::toString);
        } finally {
            System.setProperty("robosim.root", old == null ? "" : old);
            if (old == null) {
                System.clearProperty("robosim.root");
            }
        }
        List<String> lines = out.toString().lines().toList();
        assertEquals(1, lines.size(), out::toString);
        return lines.get(0);
    }

    /** @return the README's first Java code block: the tour's first program */
    private static String firstJavaProgram(Path readme) throws Exception {
        String text = Files.readString(readme);
        int start = text.indexOf("```java\n");
        assertTrue(start >= 0, "README.md has a ```java block");
        start += "```java\n".length();
        String code = text.substring(start, text.indexOf("```", start));
        assertTrue(code.contains("public class Square"), "the README's first program is class Square:\n" + code);
        return code;
    }
}
