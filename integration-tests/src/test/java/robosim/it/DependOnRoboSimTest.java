package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The "Depending on RoboSim" of docs/BUILDING.md: a project of one's own, with a {@code pom.xml} that depends
 * on {@code robosim:aria-api}, builds against RoboSim's artifacts as {@code mvn install} puts them
 * in a local repository. The test lays the artifacts out so in a local repository of its own (the
 * poms, and each module's jar, or one packed from its classes when the jars were not built),
 * and runs Maven on the project offline: the plugins and the libraries come from the build's own
 * local repository, read as a file repository, so nothing is downloaded.
 */
@Timeout(value = 5, unit = TimeUnit.MINUTES)
class DependOnRoboSimTest {
    private static final String VERSION = "0.1.0-SNAPSHOT";
    /** aria-api and the modules it needs. */
    private static final List<String> MODULES = List.of("protocol", "pioneer", "robot-params", "hardware-sim", "map-format",
            "aria-api");

    @TempDir
    Path dir;

    @Test
    void aProjectOfOnesOwnThatDependsOnAriaApiCompilesAgainstTheInstalledArtifactsOffline() throws Exception {
        String m2 = System.getProperty("robosim.localRepository");
        assumeTrue(m2 != null && Files.isDirectory(Path.of(m2)),
                "run by Maven (which names its local repository in robosim.localRepository)");
        Path mvn = onPath("mvn");
        assumeTrue(mvn != null, "no mvn on the PATH");
        Path root = LocalEnvironment.root();
        Path repo = dir.resolve("repository");
        put(repo, "robosim-parent", "pom", root.resolve("pom.xml"));
        for (String m : MODULES) {
            put(repo, m, "pom", root.resolve(m).resolve("pom.xml"));
            Path jar = root.resolve(m).resolve("target").resolve(m + "-" + VERSION + ".jar");
            put(repo, m, "jar", Files.isRegularFile(jar) ? jar : packed(root.resolve(m).resolve("target/classes")));
        }
        Path project = project(dir.resolve("my-robot"));
        Path settings = Files.writeString(dir.resolve("settings.xml"), """
                <settings>
                  <mirrors>
                    <mirror><id>build-repository</id><mirrorOf>*</mirrorOf><url>%s</url></mirror>
                  </mirrors>
                </settings>
                """.formatted(Path.of(m2).toUri()));

        List<String> command = new ArrayList<>(List.of(mvn.toString(), "-B", "-o", "-q",
                "-Daether.offline.protocols=file", "-Dmaven.repo.local=" + repo, "-s", settings.toString(), "compile"));
        Path log = dir.resolve("mvn.log");
        Process p = new ProcessBuilder(command).directory(project.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        try {
            assertTrue(p.waitFor(4, TimeUnit.MINUTES), "mvn compile ended within 4 minutes");
        } finally {
            p.destroyForcibly();
        }
        assertEquals(0, p.exitValue(), "mvn compile of a project depending on robosim:aria-api:\n" + Files.readString(log));
        assertTrue(Files.isRegularFile(project.resolve("target/classes/my/robot/FirstRobot.class")),
                "the program was compiled");
        assertTrue(Files.isDirectory(repo.resolve("com/fasterxml/jackson/core/jackson-databind")),
                "aria-api's libraries came along as dependencies of its dependencies");
    }

    /** The pom.xml of docs/BUILDING.md and a program using the ARIA API. */
    private static Path project(Path project) throws IOException {
        Files.createDirectories(project.resolve("src/main/java/my/robot"));
        Files.writeString(project.resolve("pom.xml"), """
                <project xmlns="http://maven.apache.org/POM/4.0.0">
                  <modelVersion>4.0.0</modelVersion>
                  <groupId>my</groupId>
                  <artifactId>my-robot</artifactId>
                  <version>1.0</version>
                  <properties>
                    <maven.compiler.release>17</maven.compiler.release>
                    <project.build.sourceEncoding>UTF-8</project.build.sourceEncoding>
                  </properties>
                  <dependencies>
                    <dependency>
                      <groupId>robosim</groupId>
                      <artifactId>aria-api</artifactId>
                      <version>0.1.0-SNAPSHOT</version>
                    </dependency>
                  </dependencies>
                  <build>
                    <pluginManagement>
                      <plugins>
                        <plugin><artifactId>maven-compiler-plugin</artifactId><version>3.13.0</version></plugin>
                        <plugin><artifactId>maven-resources-plugin</artifactId><version>3.3.1</version></plugin>
                      </plugins>
                    </pluginManagement>
                  </build>
                </project>
                """);
        Files.writeString(project.resolve("src/main/java/my/robot/FirstRobot.java"), """
                package my.robot;

                import robosim.aria.ArRobot;
                import robosim.aria.ArUtil;

                public class FirstRobot {
                    public static void main(String[] args) {
                        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
                        if (!robot.blockingConnect()) {
                            throw new IllegalStateException(robot.getConnectionError());
                        }
                        robot.enableMotors();
                        robot.move(1000);
                        while (!robot.isMoveDone()) {
                            ArUtil.sleep(100);
                        }
                        robot.disconnect();
                    }
                }
                """);
        return project;
    }

    /** Puts a module's file where {@code mvn install} would in a local repository. */
    private static void put(Path repo, String artifact, String extension, Path file) throws IOException {
        assertTrue(Files.isRegularFile(file), "built: " + file);
        Path to = repo.resolve("robosim").resolve(artifact).resolve(VERSION)
                .resolve(artifact + "-" + VERSION + "." + extension);
        Files.createDirectories(to.getParent());
        Files.copy(file, to);
    }

    /** @return a jar of a module's compiled classes */
    private Path packed(Path classes) throws IOException {
        assertTrue(Files.isDirectory(classes), "compiled: " + classes);
        Path jar = Files.createTempFile(dir, "classes", ".jar");
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out);
             Stream<Path> files = Files.walk(classes)) {
            for (Path f : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator) {
                j.putNextEntry(new ZipEntry(classes.relativize(f).toString().replace('\\', '/')));
                Files.copy(f, j);
                j.closeEntry();
            }
        }
        return jar;
    }

    private static Path onPath(String program) {
        for (String d : System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)) {
            Path p = Path.of(d, program);
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }
}
