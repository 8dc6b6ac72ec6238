package robosim.viewer.window;

import java.awt.BorderLayout;
import java.awt.image.BufferedImage;
import javax.swing.JPanel;

/**
 * The window's content: the display controls above the world view, the panel of the robot last
 * clicked beside it, then the replay controls when replaying, and the status bar. It needs no screen: {@link #screenshot(int, int)} paints it into
 * an image, as the tests do.
 */
public final class ViewerPane extends JPanel {
    private static final long serialVersionUID = 1L;

    private final WorldView view;
    private final DisplayControls controls;
    private final StatusBar status;
    private final PlaybackControls playback;
    private final RobotPanel robot;

    /**
     * A pane for a live run.
     *
     * @param model what to show
     * @param state how to show it
     */
    public ViewerPane(ViewModel model, ViewState state) {
        this(model, state, null);
    }

    /**
     * A pane for a replay.
     *
     * @param model  what to show
     * @param state  how to show it
     * @param player the player, or {@code null} for a live run
     */
    public ViewerPane(ViewModel model, ViewState state, ReplayPlayer player) {
        super(new BorderLayout());
        view = new WorldView(model, state);
        controls = new DisplayControls(model, state, view);
        status = new StatusBar(model);
        playback = player == null ? null : new PlaybackControls(player);
        add(controls, BorderLayout.NORTH);
        add(view, BorderLayout.CENTER);
        robot = new RobotPanel(model);
        add(robot, BorderLayout.EAST);
        JPanel south = new JPanel(new BorderLayout());
        if (playback != null) {
            south.add(playback, BorderLayout.NORTH);
        }
        south.add(status, BorderLayout.SOUTH);
        add(south, BorderLayout.SOUTH);
    }

    /**
     * Lays the pane out at a size and paints it, with all its panels, into an image.
     *
     * @param width  width, px
     * @param height height, px
     * @return the image
     */
    public BufferedImage screenshot(int width, int height) {
        setSize(width, height);
        layoutAll(this);
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = image.createGraphics();
        try {
            printAll(g);
        } finally {
            g.dispose();
        }
        return image;
    }

    private static void layoutAll(java.awt.Container c) {
        c.doLayout();
        for (java.awt.Component child : c.getComponents()) {
            if (child instanceof java.awt.Container inner) {
                layoutAll(inner);
            }
        }
    }

    /** @return the world view */
    public WorldView worldView() {
        return view;
    }

    /** @return the display controls */
    public DisplayControls displayControls() {
        return controls;
    }

    /** @return the panel of the robot last clicked (hidden while none is) */
    public RobotPanel robotPanel() {
        return robot;
    }

    /** @return the status bar */
    public StatusBar statusBar() {
        return status;
    }

    /** @return the replay controls, or {@code null} for a live run */
    public PlaybackControls playbackControls() {
        return playback;
    }
}
