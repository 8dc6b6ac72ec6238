package robosim.cli;

import java.io.File;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.List;

/** Where robot programs' classes are: {@code --classpath} of {@code robot}, and of {@code env} for its in-process programs. */
final class ProgramClasspath {
    private ProgramClasspath() {
    }

    /**
     * @param classpath directories and jars, {@code :}-separated, or null
     * @return a loader of RoboSim's classes and those on {@code classpath}
     * @throws IllegalArgumentException naming the entry, if one does not exist
     */
    static ClassLoader loader(String classpath) {
        ClassLoader robosim = ProgramClasspath.class.getClassLoader();
        if (classpath == null) {
            return robosim;
        }
        List<URL> urls = new ArrayList<>();
        for (String p : classpath.split(File.pathSeparator)) {
            if (p.isEmpty()) {
                continue;
            }
            File f = new File(p);
            if (!f.exists()) {
                throw new IllegalArgumentException("'" + p + "' was supplied for --classpath: there is no such directory or jar");
            }
            try {
                urls.add(f.toURI().toURL());
            } catch (MalformedURLException e) {
                throw new IllegalArgumentException("'" + p + "' was supplied for --classpath: " + e.getMessage(), e);
            }
        }
        return new URLClassLoader(urls.toArray(new URL[0]), robosim);
    }
}
