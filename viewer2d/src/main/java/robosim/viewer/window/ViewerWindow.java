package robosim.viewer.window;

import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.concurrent.CountDownLatch;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

/** Puts a {@link ViewerPane} in a window on the screen and tells when the user closes it. */
public final class ViewerWindow {
    private final JFrame frame;
    private final CountDownLatch closed = new CountDownLatch(1);

    private ViewerWindow(String title, ViewerPane pane) {
        frame = new JFrame(title);
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        frame.setContentPane(pane);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                closed.countDown();
            }
        });
        frame.pack();
        frame.setLocationByPlatform(true);
        frame.setVisible(true);
    }

    /**
     * Opens a window on the Swing event thread.
     *
     * @param title the window's title
     * @param pane  its content, built on the event thread
     * @return the window
     * @throws HeadlessException    if there is no screen to open it on
     * @throws InterruptedException if interrupted while it opens
     */
    public static ViewerWindow open(String title, ViewerPane pane) throws InterruptedException {
        if (GraphicsEnvironment.isHeadless()) {
            throw new HeadlessException("no display: Java runs headless (set DISPLAY, or draw PNG files instead)");
        }
        ViewerWindow[] window = new ViewerWindow[1];
        try {
            SwingUtilities.invokeAndWait(() -> window[0] = new ViewerWindow(title, pane));
        } catch (java.lang.reflect.InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException r) {
                throw r;
            }
            throw new IllegalStateException(cause);
        }
        return window[0];
    }

    /**
     * Waits until the user closes the window.
     *
     * @throws InterruptedException if interrupted
     */
    public void awaitClosed() throws InterruptedException {
        closed.await();
    }
}
