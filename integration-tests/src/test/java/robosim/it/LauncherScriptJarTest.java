package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarOutputStream;
import java.util.zip.ZipEntry;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code bin/robosim} runs the launcher's own jar when {@code mvn verify} has put its -javadoc and
 * -sources jars beside it (it once took the -javadoc jar, which sorts first, and found no main
 * class). The script runs in a copy of the project's layout whose launcher jar holds a stand-in
 * {@code robosim.cli.Main}, built and up to date, so it builds nothing.
 */
@Timeout(value = 2, unit = TimeUnit.MINUTES)
class LauncherScriptJarTest {
    @TempDir
    Path root;

    @Test
    void binRobosimRunsTheLauncherJarNotTheJavadocOrSourcesJarBesideIt() throws Exception {
        Path script = Files.copy(LocalEnvironment.root().resolve("bin/robosim"), Files.createDirectories(root.resolve("bin")).resolve("robosim"));
        Path target = Files.createDirectories(root.resolve("launcher/target/lib"));
        Path src = Files.createDirectories(root.resolve("stand-in/robosim/cli"));
        Files.writeString(src.resolve("Main.java"), """
                package robosim.cli;
                public class Main {
                    public static void main(String[] args) {
                        System.out.println("the launcher's Main " + String.join(" ", args));
                    }
                }
                """);
        Path classes = Files.createDirectories(root.resolve("stand-in/classes"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", classes.toString(),
                src.resolve("Main.java").toString()));
        jar(target.getParent().resolve("launcher-0.1.0-SNAPSHOT.jar"), classes.resolve("robosim/cli/Main.class"));
        jar(target.getParent().resolve("launcher-0.1.0-SNAPSHOT-javadoc.jar"), null);
        jar(target.getParent().resolve("launcher-0.1.0-SNAPSHOT-sources.jar"), null);
        Files.deleteIfExists(src.resolve("Main.java")); // a newer source would make the script build
        Files.writeString(target.getParent().resolve(".robosim-built"), "");

        ProcessBuilder pb = new ProcessBuilder(List.of("bash", script.toString(), "--help"))
                .redirectErrorStream(true);
        pb.environment().put("ROBOSIM_JAVA", Path.of(System.getProperty("java.home"), "bin", "java").toString());
        Process p = pb.start();
        try {
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "bin/robosim ended");
            String out = new String(p.getInputStream().readAllBytes());
            assertEquals(0, p.exitValue(), out);
            assertEquals("the launcher's Main --help", out.strip());
        } finally {
            p.destroyForcibly();
        }
    }

    /** Writes a jar holding robosim/cli/Main.class, or nothing. */
    private static void jar(Path jar, Path mainClass) throws Exception {
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out)) {
            if (mainClass != null) {
                j.putNextEntry(new ZipEntry("robosim/cli/Main.class"));
                Files.copy(mainClass, j);
                j.closeEntry();
            }
        }
    }
}
