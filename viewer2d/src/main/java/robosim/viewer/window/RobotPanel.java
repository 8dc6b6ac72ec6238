package robosim.viewer.window;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import robosim.protocol.Snapshot;
import robosim.protocol.Snapshot.RobotView;
import robosim.protocol.WorldDescription.RobotInfo;
import robosim.viewer.draw.Departures;

/**
 * The panel of the robot last clicked: its true and odometric pose and how far apart they are, its
 * velocities, whether it is stalled or connected, a plot of its sonar and laser readings, and the
 * latest messages it sent, received or said. Hidden while no robot is chosen.
 */
public final class RobotPanel extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient ViewModel model;
    private final JTextArea text = new JTextArea();
    private final SensorPlot plot;

    /** @param model what the window shows, and which robot is chosen */
    public RobotPanel(ViewModel model) {
        super(new BorderLayout(0, 4));
        this.model = model;
        plot = new SensorPlot(model);
        setBorder(BorderFactory.createEmptyBorder(4, 6, 4, 6));
        setPreferredSize(new Dimension(280, 400));
        text.setEditable(false);
        text.setLineWrap(true);
        text.setWrapStyleWord(true);
        JButton close = new JButton("Close");
        close.addActionListener(e -> model.select(null));
        add(plot, BorderLayout.NORTH);
        add(new JScrollPane(text), BorderLayout.CENTER);
        add(close, BorderLayout.SOUTH);
        model.observe(this::refresh);
        refresh();
    }

    private void refresh() {
        RobotView robot = chosen(model);
        boolean show = robot != null;
        if (show != isVisible()) {
            setVisible(show);
            if (getParent() != null) {
                getParent().revalidate();
            }
        }
        if (show) {
            String shown = String.join("\n", lines(model, robot));
            if (!shown.equals(text.getText())) {
                text.setText(shown);
                text.setCaretPosition(0);
            }
            plot.repaint();
        }
    }

    /**
     * @param model what the window shows
     * @return the chosen robot as the current snapshot has it, or {@code null}
     */
    static RobotView chosen(ViewModel model) {
        Snapshot snapshot = model.snapshot();
        if (model.selected() == null || snapshot == null) {
            return null;
        }
        for (RobotView r : snapshot.robots()) {
            if (model.selected().equals(r.name())) {
                return r;
            }
        }
        return null;
    }

    /**
     * The panel's text about one robot, for example {@code true pose: x 2700 mm, y 1500 mm, heading 0.0°}.
     *
     * @param model what the window shows
     * @param r     the robot
     * @return the lines
     */
    public static List<String> lines(ViewModel model, RobotView r) {
        List<String> lines = new ArrayList<>();
        boolean gone = model.snapshot() != null && Departures.gone(model.snapshot(), r);
        lines.add(r.name() + ": " + (r.connected() ? "connected" : gone ? "gone from the run" : "not connected yet")
                + (r.stalled() ? ", STALLED (pushing against something)" : ", moving freely"));
        lines.add(String.format(Locale.ROOT, "true pose: x %.0f mm, y %.0f mm, heading %.1f°", r.x(), r.y(), r.th()));
        lines.add(String.format(Locale.ROOT, "believed (odometry): x %.0f mm, y %.0f mm, heading %.1f°", r.odoX(),
                r.odoY(), r.odoTh()));
        lines.add(String.format(Locale.ROOT, "odometry error: %.0f mm, %.1f°", Math.hypot(r.odoX() - r.x(), r.odoY() - r.y()),
                Math.abs(Math.IEEEremainder(r.odoTh() - r.th(), 360))));
        lines.add(String.format(Locale.ROOT, "velocity: %.0f mm/s, turning %.1f°/s", r.vel(), r.rotVel()));
        int[] sonar = r.sonar();
        if (sonar != null && sonar.length > 0) {
            StringBuilder s = new StringBuilder("sonar (mm):");
            for (int i = 0; i < sonar.length; i++) {
                s.append(' ').append(i).append(':').append(sonar[i]);
            }
            lines.add(s.toString());
        }
        int[] laser = r.laser();
        if (laser != null && laser.length > 0) {
            int nearest = Integer.MAX_VALUE;
            for (int v : laser) {
                nearest = v > 0 ? Math.min(nearest, v) : nearest;
            }
            lines.add(laser.length + " laser readings" + (nearest == Integer.MAX_VALUE ? "" : ", nearest " + nearest + " mm"));
        }
        lines.add("messages (latest last):");
        int before = lines.size();
        for (String m : model.messages()) {
            if (m.contains(" " + r.name() + " ") || m.contains(": " + r.name() + " to ")) {
                lines.add("  " + m);
            }
        }
        if (lines.size() == before) {
            lines.add("  none yet");
        }
        return lines;
    }

    /**
     * @param model what the window shows
     * @param name  a robot's name
     * @return its description in the world, or {@code null}
     */
    static RobotInfo info(ViewModel model, String name) {
        if (model.world() == null) {
            return null;
        }
        for (RobotInfo info : model.world().robots()) {
            if (info.name().equals(name)) {
                return info;
            }
        }
        return null;
    }

    /** @return the text shown */
    public String shown() {
        return text.getText();
    }
}
