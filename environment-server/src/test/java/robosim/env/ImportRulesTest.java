package robosim.env;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The simulation core ({@code robosim.env.core}) stays plain deterministic Java: no network, no
 * drawing, no threads, no clocks, no unseeded randomness (every random stream comes from the run's seed). It is
 * stepped by the TCP layer, never the other way round. The GeometryClient it builds on is pure
 * geometry: no I/O and no drawing, so the Environment, the viewer and tests can all use it.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ImportRulesTest {
    private static final String CORE = "src/main/java/robosim/env/core";
    /** The camera's rendering, which the core calls while it reads the sensors. */
    private static final String CAMERA = "src/main/java/robosim/env/camera";
    /** The robots' sensors, which the core calls each step. */
    private static final String SENSORS = "src/main/java/robosim/env/sensors";
    private static final String GEOMETRY = "../geometry-client/src/main";

    static Stream<Arguments> geometryRules() {
        return Stream.of(
                Arguments.of("the network (java.net)", "\\bjava\\.net\\."),
                Arguments.of("I/O (java.io)", "\\bjava\\.io\\."),
                Arguments.of("files (java.nio.file)", "\\bjava\\.nio\\.file\\b"),
                Arguments.of("channels (java.nio.channels)", "\\bjava\\.nio\\.channels\\b"),
                Arguments.of("AWT (java.awt)", "\\bjava\\.awt\\b"),
                Arguments.of("Swing (javax.swing)", "\\bjavax\\.swing\\b"));
    }

    @ParameterizedTest(name = "geometry-client does not use {0}")
    @MethodSource("geometryRules")
    void geometryClientDoesNotUse(String what, String regex) throws IOException {
        assertEquals(List.of(), offences(sources(GEOMETRY), Pattern.compile(regex)), "geometry-client must not use " + what);
    }

    static Stream<Arguments> rules() {
        return Stream.of(
                Arguments.of("the network (java.net)", "\\bjava\\.net\\."),
                Arguments.of("channels (java.nio.channels)", "\\bjava\\.nio\\.channels\\b"),
                Arguments.of("AWT (java.awt)", "\\bjava\\.awt\\b"),
                Arguments.of("Swing (javax.swing)", "\\bjavax\\.swing\\b"),
                Arguments.of("threads and executors (java.util.concurrent)", "\\bjava\\.util\\.concurrent\\b"),
                Arguments.of("threads (new Thread, Thread.sleep)", "\\bnew\\s+Thread\\s*\\(|\\bThread\\s*\\.\\s*sleep\\b"),
                Arguments.of("the Environment's TCP layer (robosim.env.net)", "\\brobosim\\.env\\.net\\b"),
                Arguments.of("the world file reader (robosim.env.world.xml)", "\\brobosim\\.env\\.world\\.xml\\b"),
                Arguments.of("the map file reader (robosim.env.world.map)", "\\brobosim\\.env\\.world\\.map\\b"),
                Arguments.of("the map file reader (robosim.map)", "\\brobosim\\.map\\b"),
                Arguments.of("the wall clock (System.currentTimeMillis)", "\\bSystem\\s*\\.\\s*currentTimeMillis\\b"),
                Arguments.of("the wall clock (System.nanoTime)", "\\bSystem\\s*\\.\\s*nanoTime\\b"),
                Arguments.of("unseeded randomness (new Random())", "\\bnew\\s+(java\\.(util|security)\\.)?(Secure|Splittable)?Random\\s*\\(\\s*\\)"),
                Arguments.of("the system's entropy (SecureRandom)", "\\bSecureRandom\\b"),
                Arguments.of("unseeded randomness (Math.random)", "\\bMath\\s*\\.\\s*random\\b"));
    }

    @ParameterizedTest(name = "the core does not use {0}")
    @MethodSource("rules")
    void theCoreDoesNotUse(String what, String regex) throws IOException {
        assertEquals(List.of(), offences(sources(CORE), Pattern.compile(regex)), "robosim.env.core must not use " + what);
    }

    @ParameterizedTest(name = "the sensors do not use {0}")
    @MethodSource("rules")
    void theSensorsDoNotUse(String what, String regex) throws IOException {
        List<Path> sensors = sources(SENSORS);
        assertTrue(sensors.stream().anyMatch(f -> f.endsWith("SensorKinds.java")), "scanned " + sensors);
        assertEquals(List.of(), offences(sensors, Pattern.compile(regex)), "robosim.env.sensors must not use " + what);
    }

    @ParameterizedTest(name = "the camera does not use {0}")
    @MethodSource("rules")
    void theCameraDoesNotUse(String what, String regex) throws IOException {
        List<Path> camera = sources(CAMERA);
        assertTrue(camera.stream().anyMatch(f -> f.endsWith("CameraImage.java")), "scanned " + camera);
        assertEquals(List.of(), offences(camera, Pattern.compile(regex)), "robosim.env.camera must not use " + what);
    }

    @Test
    void theScanFindsTheSources() throws IOException {
        assertTrue(sources(CORE).stream().anyMatch(f -> f.endsWith("Simulation.java")), "scanned " + sources(CORE));
        assertTrue(sources(GEOMETRY).stream().anyMatch(f -> f.endsWith("GeometryClient.java")), "scanned " + sources(GEOMETRY));
    }

    private static List<String> offences(List<Path> files, Pattern forbidden) throws IOException {
        List<String> found = new ArrayList<>();
        for (Path file : files) {
            found.addAll(offences(file, Files.readString(file), forbidden));
        }
        return found;
    }

    @Test
    void theRulesCatchAForbiddenImportAndIgnoreComments() {
        String source = """
                package robosim.env.core;
                // java.net.Socket is mentioned in a comment only
                /* System.nanoTime() in a block comment */
                import java.net.Socket;
                class Bad { long t = System . nanoTime(); String s = "java.awt.Color"; }
                """;
        assertEquals(List.of("Bad.java:4: import java.net.Socket;"),
                offences(Path.of("Bad.java"), source, Pattern.compile("\\bjava\\.net\\.")));
        assertEquals(List.of("Bad.java:5: class Bad { long t = System . nanoTime(); String s = \"java.awt.Color\"; }"),
                offences(Path.of("Bad.java"), source, Pattern.compile("\\bSystem\\s*\\.\\s*nanoTime\\b")));
        assertEquals(List.of(), offences(Path.of("Bad.java"), source, Pattern.compile("\\bjava\\.awt\\b")),
                "a string literal is not a use");
    }

    private static List<Path> sources(String relative) throws IOException {
        Path dir = moduleDir().resolve(relative).normalize();
        assertTrue(Files.isDirectory(dir), "no sources at " + dir.toAbsolutePath());
        try (Stream<Path> files = Files.walk(dir)) {
            return files.filter(f -> f.toString().endsWith(".java")).sorted().toList();
        }
    }

    /** The module directory: surefire's working directory, or its child when run from the root. */
    private static Path moduleDir() {
        Path cwd = Path.of("").toAbsolutePath();
        return Files.isDirectory(cwd.resolve(CORE)) ? cwd : cwd.resolve("environment-server");
    }

    /** Lines of {@code source} whose code (comments and string literals removed) matches. */
    static List<String> offences(Path file, String source, Pattern forbidden) {
        String[] code = stripCommentsAndStrings(source).split("\n", -1);
        String[] original = source.split("\n", -1);
        List<String> found = new ArrayList<>();
        for (int i = 0; i < code.length; i++) {
            if (forbidden.matcher(code[i]).find()) {
                found.add(file.getFileName() + ":" + (i + 1) + ": " + original[i].strip());
            }
        }
        return found;
    }

    /** Blanks comments, string and char literals, keeping every newline so lines still match. */
    static String stripCommentsAndStrings(String s) {
        StringBuilder out = new StringBuilder(s.length());
        int i = 0;
        while (i < s.length()) {
            char c = s.charAt(i);
            if (s.startsWith("//", i)) {
                while (i < s.length() && s.charAt(i) != '\n') {
                    i++;
                }
            } else if (s.startsWith("/*", i)) {
                int end = s.indexOf("*/", i + 2);
                end = end < 0 ? s.length() : end + 2;
                out.append(s.substring(i, end).replaceAll("[^\n]", " "));
                i = end;
            } else if (s.startsWith("\"\"\"", i)) {
                int end = s.indexOf("\"\"\"", i + 3);
                end = end < 0 ? s.length() : end + 3;
                out.append(s.substring(i, end).replaceAll("[^\n]", " "));
                i = end;
            } else if (c == '"' || c == '\'') {
                int j = i + 1;
                while (j < s.length() && s.charAt(j) != c && s.charAt(j) != '\n') {
                    j += s.charAt(j) == '\\' ? 2 : 1;
                }
                j = Math.min(j + 1, s.length());
                out.append(" ".repeat(j - i));
                i = j;
            } else {
                out.append(c);
                i++;
            }
        }
        return out.toString();
    }
}
