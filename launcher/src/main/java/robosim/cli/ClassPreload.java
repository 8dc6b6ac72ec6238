package robosim.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.logging.Logger;
import java.util.stream.Stream;

/**
 * Loads the classes of a server's packages before it takes connections. A class is read from its
 * jar or folder the first time it is used; under a full file table (the very state a flood of
 * connections brings, see docs/SECURITY.md) a class used for the first time then cannot be read,
 * and the server would fail where it should keep going. Loading does not initialise: no static
 * code runs early.
 */
final class ClassPreload {
    private static final Logger LOG = Logger.getLogger(ClassPreload.class.getName());

    private ClassPreload() {
    }

    /**
     * Loads every class of the anchors' jars or folders whose name starts with one of the prefixes.
     *
     * @param prefixes package prefixes, for example {@code robosim.env.}
     * @param anchors  one class of each jar or folder to load from
     * @return the count of classes loaded
     */
    static int load(List<String> prefixes, Class<?>... anchors) {
        int n = 0;
        for (Class<?> anchor : anchors) {
            for (String name : classNames(anchor)) {
                if (prefixes.stream().anyMatch(name::startsWith)) {
                    try {
                        Class.forName(name, false, anchor.getClassLoader());
                        n++;
                    } catch (ClassNotFoundException | LinkageError e) {
                        LOG.fine(() -> "not preloaded: " + name + ": " + e);
                    }
                }
            }
        }
        return n;
    }

    private static List<String> classNames(Class<?> anchor) {
        CodeSource source = anchor.getProtectionDomain().getCodeSource();
        List<String> names = new ArrayList<>();
        if (source == null) {
            return names;
        }
        try {
            Path where = Path.of(source.getLocation().toURI());
            if (Files.isDirectory(where)) {
                try (Stream<Path> files = Files.walk(where)) {
                    files.filter(p -> p.toString().endsWith(".class"))
                            .forEach(p -> names.add(className(where.relativize(p).toString())));
                }
            } else if (Files.isRegularFile(where)) {
                try (JarFile jar = new JarFile(where.toFile())) {
                    for (Enumeration<JarEntry> e = jar.entries(); e.hasMoreElements();) {
                        String entry = e.nextElement().getName();
                        if (entry.endsWith(".class")) {
                            names.add(className(entry));
                        }
                    }
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list the classes of " + source.getLocation(), e);
        } catch (URISyntaxException | IllegalArgumentException e) {
            LOG.fine(() -> "cannot list the classes of " + source.getLocation() + ": " + e);
        }
        return names;
    }

    private static String className(String path) {
        return path.substring(0, path.length() - ".class".length()).replace('/', '.').replace('\\', '.');
    }
}
