package robosim.panel.model;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * What a new run is started with: the world, the seed, the two ports and the address to listen on,
 * checked as the user typed them, turned into the arguments of {@code robosim env}.
 *
 * @param world      the world file
 * @param seed       the seed of everything random
 * @param robotPort  the robot port, 0 for any free one
 * @param viewerPort the viewer port, 0 for any free one
 * @param bind       the address to listen on
 */
public record RunSettings(Path world, long seed, int robotPort, int viewerPort, String bind) {
    /**
     * Reads the fields of the panel's "new run" form.
     *
     * @param world      the world file's path
     * @param seed       the seed as typed
     * @param robotPort  the robot port as typed (0 or empty: any free one)
     * @param viewerPort the viewer port as typed (0 or empty: any free one)
     * @param bind       the address as typed (empty: 127.0.0.1)
     * @return the settings
     * @throws IllegalArgumentException naming the field, the value and the rule
     */
    public static RunSettings parse(String world, String seed, String robotPort, String viewerPort, String bind) {
        if (world == null || world.isBlank()) {
            throw new IllegalArgumentException("World: choose a world file (.xml) or an ARIA map (.map)");
        }
        Path w = Path.of(world.trim());
        if (!Files.isRegularFile(w)) {
            throw new IllegalArgumentException("World: no such file: " + w);
        }
        long s;
        try {
            s = Long.parseLong(seed.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("Seed: a whole number (64 bits), got '" + seed + "'");
        }
        String b = bind == null || bind.isBlank() ? "127.0.0.1" : bind.trim();
        if (!b.matches("[A-Za-z0-9.:\\-\\[\\]]{1,255}")) {
            throw new IllegalArgumentException("Bind: a host name or an IP address, got '" + bind + "'");
        }
        int rp = port("Robot port", robotPort);
        int vp = port("Viewer port", viewerPort);
        if (rp != 0 && rp == vp) {
            throw new IllegalArgumentException("Viewer port: must differ from the robot port, both are " + rp);
        }
        return new RunSettings(w, s, rp, vp, b);
    }

    private static int port(String field, String text) {
        if (text == null || text.isBlank()) {
            return 0;
        }
        int p;
        try {
            p = Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            p = -1;
        }
        if (p < 0 || p > 65535) {
            throw new IllegalArgumentException(field + ": 0 (any free port) or a port from 1 to 65535, got '" + text + "'");
        }
        return p;
    }

    /**
     * @param tokenFile where the Environment writes the run secret
     * @return the arguments of {@code robosim env}, from the subcommand's name on
     */
    public List<String> envArguments(Path tokenFile) {
        return List.of("env", world.toString(), "--seed", Long.toString(seed), "--robot-port",
                Integer.toString(robotPort), "--viewer-port", Integer.toString(viewerPort), "--bind", bind,
                "--token-file", tokenFile.toString());
    }
}
