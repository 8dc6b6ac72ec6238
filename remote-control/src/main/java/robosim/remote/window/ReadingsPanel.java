package robosim.remote.window;

import java.awt.BorderLayout;
import java.awt.Font;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.DefaultListModel;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import robosim.remote.Inbox;
import robosim.remote.ReadingLines;
import robosim.remote.Readings;
import robosim.remote.robot.RemoteRobot;

/** The live readings: the polar plot, the lines of {@link ReadingLines}, and the messages received. */
final class ReadingsPanel extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient RemoteRobot robot;
    private final PolarPlot plot;
    private final JTextArea lines = new JTextArea(7, 28);
    private final DefaultListModel<String> messages = new DefaultListModel<>();
    private final JLabel messageCount = new JLabel("messages received: 0");
    private transient Readings shown;
    private long messagesShown = -1;

    ReadingsPanel(RemoteRobot robot) {
        super(new BorderLayout(0, 4));
        this.robot = robot;
        this.plot = new PolarPlot(robot::latest);
        lines.setEditable(false);
        lines.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        lines.setName("readings");
        JList<String> list = new JList<>(messages);
        list.setName("messages");
        list.setVisibleRowCount(6);
        JPanel south = new JPanel(new BorderLayout());
        south.add(messageCount, BorderLayout.NORTH);
        south.add(new JScrollPane(list), BorderLayout.CENTER);
        JPanel top = new JPanel(new BorderLayout(0, 4));
        top.add(plot, BorderLayout.CENTER);
        top.add(lines, BorderLayout.SOUTH);
        add(top, BorderLayout.CENTER);
        add(south, BorderLayout.SOUTH);
        setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        refresh();
    }

    /** On the event thread: shows the latest readings and messages, if they changed. */
    void refresh() {
        Readings r = robot.latest();
        if (r != shown || shown == null) {
            shown = r;
            lines.setText(String.join("\n", ReadingLines.of(r)));
            plot.repaint();
        }
        Inbox inbox = robot.inbox();
        long total = inbox.total();
        if (total != messagesShown) {
            messagesShown = total;
            List<String> kept = inbox.lines();
            messages.clear();
            messages.addAll(kept);
            messageCount.setText("messages received: " + total);
        }
    }

    /** @return the readings as shown */
    String readingsText() {
        return lines.getText();
    }
}
