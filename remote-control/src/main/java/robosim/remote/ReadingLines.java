package robosim.remote;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** What the readings panel says of one step's {@link Readings}, a line each. */
public final class ReadingLines {
    private ReadingLines() {
    }

    /**
     * @param r the readings, or null before the first step
     * @return the lines
     */
    public static List<String> of(Readings r) {
        if (r == null) {
            return List.of("waiting for the first step");
        }
        List<String> lines = new ArrayList<>();
        lines.add(f("step %d, t = %.1f s", r.step(), r.timeMs() / 1000.0));
        lines.add(f("pose x %.0f mm, y %.0f mm, th %.1f°", r.x(), r.y(), r.th()));
        lines.add(f("vel %.0f mm/s, rotVel %.1f deg/s", r.vel(), r.rotVel()));
        lines.add(r.stalled() ? "STALLED: a collision stopped the robot" : "stall: no");
        if (!r.sonarOn()) {
            lines.add("sonar: off");
        } else {
            lines.add(r.sonar().isEmpty() ? "sonar: on, no readings yet"
                    : f("sonar: %d rays, nearest %d mm", r.sonar().size(), r.nearestSonar()));
        }
        lines.add(!r.laserOn() ? "laser: off" : f("laser: on, %d hits in range", r.laser().size()));
        Readings.Heat h = r.heat();
        if (h == null) {
            lines.add("heat: off");
        } else if (h.intensity() <= 0) {
            lines.add("heat: on, nothing in view");
        } else {
            lines.add(f("heat: %.2f at bearing %.0f°, %.0f mm", h.intensity(), h.bearing(), h.distance()));
        }
        return lines;
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }
}
