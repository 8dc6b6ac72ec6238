package robosim.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The benchmark's grid world: a square arena of 4 m cells, one p3dx at each cell centre with
 * heading (37·k mod 360)°, a 0.6 m square pillar centred 1.2 m right and 1.2 m up from each robot,
 * and walls around.
 */
public final class GridWorld {
    /** Cell size, mm. */
    public static final int CELL = 4000;

    private GridWorld() {
    }

    /**
     * Writes the grid world for {@code robots} robots as a world file.
     *
     * @param robots    how many robots, at least 1
     * @param dir       where to write it
     * @param robotFile the p3dx parameter file the world names
     * @return the world file
     * @throws IOException if it cannot be written
     */
    public static Path write(int robots, Path dir, Path robotFile) throws IOException {
        if (robots < 1) {
            throw new IllegalArgumentException(robots + " was supplied for robots: it must be at least 1");
        }
        int side = (int) Math.ceil(Math.sqrt(robots));
        int size = side * CELL;
        StringBuilder xml = new StringBuilder();
        xml.append(String.format(Locale.ROOT,
                "<world name=\"grid-%d\" width=\"%d\" height=\"%d\" stepMs=\"100\" boundary=\"true\">%n",
                robots, size, size));
        for (int k = 0; k < robots; k++) {
            int cx = (k % side) * CELL + CELL / 2;
            int cy = (k / side) * CELL + CELL / 2;
            int px = cx + 1200;
            int py = cy + 1200;
            xml.append(String.format(Locale.ROOT, "  <polygon points=\"%d,%d %d,%d %d,%d %d,%d\"/>%n",
                    px - 300, py - 300, px + 300, py - 300, px + 300, py + 300, px - 300, py + 300));
            xml.append(String.format(Locale.ROOT,
                    "  <robot name=\"b%d\" type=\"pioneer\" x=\"%d\" y=\"%d\" th=\"%d\" params=\"%s\"/>%n",
                    k, cx, cy, (37 * k) % 360, robotFile.toAbsolutePath()));
        }
        xml.append("</world>\n");
        Files.createDirectories(dir);
        Path file = dir.resolve("grid-" + robots + ".xml");
        Files.writeString(file, xml, StandardCharsets.UTF_8);
        return file;
    }
}
