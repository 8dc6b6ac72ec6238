package robosim.viewer.window;

import java.awt.BorderLayout;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextArea;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * The lines under the view: the world, the step and simulated time, the source, and the end,
 * wrapped so that a long end reason is shown whole; and on the right the world point under the
 * mouse.
 */
public final class StatusBar extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient ViewModel model;
    private final JTextArea line = new JTextArea(" ");
    private final JLabel cursor = new JLabel(" ");

    /** @param model what the window shows */
    public StatusBar(ViewModel model) {
        super(new BorderLayout(12, 0));
        this.model = model;
        setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        line.setEditable(false);
        line.setLineWrap(true);
        line.setWrapStyleWord(true);
        line.setOpaque(false);
        line.setFont(cursor.getFont());
        line.setBorder(null);
        add(line, BorderLayout.CENTER);
        add(cursor, BorderLayout.EAST);
        model.observe(this::refresh);
        refresh();
    }

    private void refresh() {
        String text = text(model);
        if (!text.equals(line.getText())) {
            line.setText(text);
            revalidate();
        }
        cursor.setText(cursorText(model.cursor()));
    }

    /**
     * The cursor readout, for example {@code x 1250 mm, y 740 mm}.
     *
     * @param xy the world point under the mouse, mm, or {@code null}
     * @return the readout, a blank when the mouse is off the world
     */
    public static String cursorText(double[] xy) {
        return xy == null ? " " : String.format(Locale.ROOT, "x %.0f mm, y %.0f mm", xy[0], xy[1]);
    }

    /**
     * The status line, for example
     * {@code world small-maze · step 120 · t = 12.0 s · 2 robots · live from localhost:3000}.
     *
     * @param model what the window shows
     * @return the line
     */
    public static String text(ViewModel model) {
        WorldDescription world = model.world();
        if (world == null) {
            return "waiting for the world" + (model.source().isEmpty() ? "" : " · " + model.source());
        }
        StringBuilder s = new StringBuilder("world ").append(world.name());
        Snapshot snapshot = model.snapshot();
        if (snapshot != null) {
            s.append(String.format(Locale.ROOT, " · step %d · t = %.1f s · %d robots", snapshot.step(),
                    snapshot.timeMs() / 1000.0, snapshot.robots().size()));
        }
        if (!model.source().isEmpty()) {
            s.append(" · ").append(model.source());
        }
        if (model.endedReason() != null) {
            s.append(" · ended: ").append(model.endedReason());
        }
        return s.toString();
    }

    /** @return the text shown */
    public String shown() {
        return line.getText();
    }

    /** @return the cursor readout shown */
    public String cursorShown() {
        return cursor.getText();
    }

    /** @return the wrapped status lines, for their layout */
    JTextArea lines() {
        return line;
    }
}
