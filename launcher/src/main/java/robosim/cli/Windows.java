package robosim.cli;

import java.awt.AWTError;
import java.awt.HeadlessException;
import java.io.PrintWriter;
import javax.swing.SwingUtilities;
import robosim.viewer.window.Displays;
import robosim.viewer.window.ViewerPane;
import robosim.viewer.window.ViewerWindow;

/** Opens the viewer's window for the commands that offer {@code --window}. */
final class Windows {
    private Windows() {
    }

    /** A pane built on the Swing event thread. */
    @FunctionalInterface
    interface PaneMaker {
        ViewerPane make();
    }

    /**
     * Turns off headless mode (the launcher starts Java headless) when a display is there. Call it
     * before anything graphical: the first AWT class loaded fixes whether Java runs headless.
     *
     * @param err     where to say why no window can be opened
     * @param command what starts that message, such as {@code robosim viewer}
     * @return true if a window can be opened; false once the reason is written to {@code err}
     */
    static boolean prepare(PrintWriter err, String command) {
        if (!Displays.displayNamed()) {
            err.println(command + ": --window needs a display, and DISPLAY is not set (draw PNG files with --png-dir instead)");
            return false;
        }
        System.setProperty("java.awt.headless", "false");
        return true;
    }

    /**
     * Builds the pane on the event thread and opens it in a window.
     *
     * @param title the window's title
     * @param maker builds the pane
     * @return the window
     * @throws IllegalStateException with the reason if no window can be opened
     * @throws InterruptedException  if interrupted
     */
    static ViewerWindow open(String title, PaneMaker maker) throws InterruptedException {
        try {
            ViewerPane[] pane = new ViewerPane[1];
            SwingUtilities.invokeAndWait(() -> pane[0] = maker.make());
            return ViewerWindow.open(title, pane[0]);
        } catch (HeadlessException | AWTError e) {
            throw new IllegalStateException("cannot open a window: " + e.getMessage(), e);
        } catch (java.lang.reflect.InvocationTargetException e) {
            throw new IllegalStateException("cannot build the window: " + e.getCause(), e.getCause());
        }
    }
}
