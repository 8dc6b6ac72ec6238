package robosim.viewer.window;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.util.Locale;

/**
 * Whether this JVM can open windows. The window tests ask it first and skip, saying why, when it
 * cannot: run them under a display ({@code xvfb-run -a mvn -B verify}, as {@code .ci/run} does).
 */
public final class Displays {
    private Displays() {
    }

    /**
     * @return null when windows can be opened here; otherwise why not, in one line that says how to
     *         get a display
     */
    public static String unavailable() {
        if (!displayNamed()) {
            return "DISPLAY is not set: run under a display, e.g. xvfb-run -a mvn -B verify";
        }
        if (Boolean.getBoolean("java.awt.headless")) {
            return "java.awt.headless is true in this JVM";
        }
        try {
            if (GraphicsEnvironment.isHeadless()
                    || GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices().length == 0) {
                return "AWT finds no screen on display " + System.getenv("DISPLAY");
            }
        } catch (HeadlessException | AWTError e) {
            return "display " + System.getenv("DISPLAY") + " cannot be opened: " + e.getMessage();
        }
        return null;
    }

    /**
     * @return false on X11 or Wayland systems when neither {@code DISPLAY} nor {@code WAYLAND_DISPLAY}
     *         names a display (where no window can open); true elsewhere
     */
    public static boolean displayNamed() {
        String os = System.getProperty("os.name", "").toLowerCase(Locale.ROOT);
        boolean x11 = !os.contains("win") && !os.contains("mac");
        return !x11 || !isBlank(System.getenv("DISPLAY")) || !isBlank(System.getenv("WAYLAND_DISPLAY"));
    }

    private static boolean isBlank(String s) {
        return s == null || s.isBlank();
    }
}
