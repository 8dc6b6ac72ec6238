package robosim.viewer.window;

import java.awt.BorderLayout;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/** The line under the view: the world, the step and simulated time, the source, and the end. */
public final class StatusBar extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient ViewModel model;
    private final JLabel label = new JLabel(" ");

    /** @param model what the window shows */
    public StatusBar(ViewModel model) {
        super(new BorderLayout());
        this.model = model;
        setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        add(label, BorderLayout.CENTER);
        model.observe(this::refresh);
        refresh();
    }

    private void refresh() {
        label.setText(text(model));
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
        return label.getText();
    }
}
