package robosim.viewer.window;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.util.Locale;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JPanel;
import javax.swing.JSlider;

/**
 * The replay's controls: to the start, a step back, play or pause, a step on, to the end, a
 * slider over the whole recording, and the speed.
 */
public final class PlaybackControls extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient ReplayPlayer player;
    private final JButton play = new JButton("Play");
    private final JSlider position;
    private final JComboBox<String> speed = new JComboBox<>();
    private boolean updating;

    /** @param player the player the controls drive */
    public PlaybackControls(ReplayPlayer player) {
        super(new BorderLayout(6, 0));
        this.player = player;
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 2));
        buttons.add(button("|<", () -> player.seek(0)));
        buttons.add(button("<", () -> player.step(-1)));
        play.addActionListener(e -> {
            if (player.playing()) {
                player.pause();
            } else {
                player.play();
            }
        });
        buttons.add(play);
        buttons.add(button(">", () -> player.step(1)));
        buttons.add(button(">|", () -> player.seek(player.size() - 1)));
        for (double s : ReplayPlayer.SPEEDS) {
            speed.addItem(label(s));
        }
        speed.setSelectedItem(label(player.speed()));
        speed.addActionListener(e -> {
            if (!updating) {
                player.setSpeed(ReplayPlayer.SPEEDS[speed.getSelectedIndex()]);
            }
        });
        buttons.add(speed);
        position = new JSlider(0, Math.max(0, player.size() - 1), Math.max(0, player.index()));
        position.addChangeListener(e -> {
            if (!updating) {
                player.seek(position.getValue());
            }
        });
        add(buttons, BorderLayout.WEST);
        add(position, BorderLayout.CENTER);
        player.observe(this::refresh);
    }

    private static JButton button(String text, Runnable action) {
        JButton b = new JButton(text);
        b.addActionListener(e -> action.run());
        return b;
    }

    /**
     * @param speed a multiple of real time
     * @return its label, such as {@code 0.25x} or {@code 4x}
     */
    static String label(double speed) {
        return (speed == Math.rint(speed) ? Long.toString((long) speed) : String.format(Locale.ROOT, "%s", speed)) + "x";
    }

    private void refresh() {
        updating = true;
        try {
            play.setText(player.playing() ? "Pause" : "Play");
            position.setValue(Math.max(0, player.index()));
            speed.setSelectedItem(label(player.speed()));
        } finally {
            updating = false;
        }
    }

    /** @return the play or pause button */
    public JButton playButton() {
        return play;
    }

    /** @return the position slider */
    public JSlider positionSlider() {
        return position;
    }
}
