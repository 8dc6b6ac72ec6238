package robosim.params;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.security.CodeSource;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * Where RoboSim's shipped robot parameter files are ({@code testLoadFiles/robots/} under the RoboSim
 * root), and which bare names stand for them.
 */
final class ShippedFiles {
    /** The system property that names the RoboSim root; {@code bin/robosim} sets it. */
    static final String ROOT_PROPERTY = "robosim.root";

    private ShippedFiles() {
    }

    /**
     * The RoboSim root: the system property {@value #ROOT_PROPERTY}; else the working directory when
     * it holds {@code testLoadFiles/robots}; else the clone this class was loaded from (a program run
     * with plain {@code java} against the jars of {@code bin/robosim classpath}, from a folder of
     * its own); else the working directory.
     */
    static Path root() {
        String property = System.getProperty(ROOT_PROPERTY);
        if (property != null) {
            return Paths.get(property);
        }
        Path here = Paths.get(".");
        if (Files.isDirectory(robots(here))) {
            return here;
        }
        Path clone = cloneOfThisClass();
        return clone != null ? clone : here;
    }

    /** @return the folder of shipped parameter files under a root */
    static Path robots(Path root) {
        return root.resolve("testLoadFiles").resolve("robots");
    }

    /**
     * @param name a bare name: {@code p3dx}, {@code p3dx.p} or {@code p3dx.xml}; no extension means
     *             ARIA's {@code .p} form
     * @return the shipped file it stands for, or empty when it is not a bare name (it holds a path
     *         separator) or there is no such shipped file
     */
    static Optional<Path> find(String name) {
        if (name.isEmpty() || name.indexOf('/') >= 0 || name.indexOf('\\') >= 0 || name.equals(".")
                || name.equals("..")) {
            return Optional.empty();
        }
        Path shipped = robots(root()).resolve(withExtension(name));
        return Files.isRegularFile(shipped) ? Optional.of(shipped) : Optional.empty();
    }

    /** @return the file name a bare name stands for: itself with an extension, else {@code NAME.p} */
    static String withExtension(String name) {
        String lower = name.toLowerCase(Locale.ROOT);
        return lower.endsWith(".p") || lower.endsWith(".xml") ? name : name + ".p";
    }

    /**
     * @return the names that find a shipped file, sorted: each {@code .p} file's name without its
     *         extension, each {@code .xml} file's with it; empty when the folder is missing
     */
    static List<String> names() {
        Path dir = robots(root());
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(Files::isRegularFile).map(p -> p.getFileName().toString())
                    .filter(n -> n.endsWith(".p") || n.endsWith(".xml"))
                    .map(n -> n.endsWith(".p") ? n.substring(0, n.length() - 2) : n)
                    .sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list the shipped parameter files in " + dir, e);
        }
    }

    /** @return the nearest folder above this class's jar or classes that holds the shipped files, or null */
    private static Path cloneOfThisClass() {
        CodeSource source = ShippedFiles.class.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return null;
        }
        try {
            for (Path p = Paths.get(source.getLocation().toURI()).toAbsolutePath(); p != null; p = p.getParent()) {
                if (Files.isDirectory(robots(p))) {
                    return p;
                }
            }
        } catch (URISyntaxException | IllegalArgumentException | SecurityException e) {
            // a location that is no file (a custom class loader's): no clone to find
        }
        return null;
    }
}
