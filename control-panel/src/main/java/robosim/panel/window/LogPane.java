package robosim.panel.window;

import java.awt.BorderLayout;
import java.awt.Font;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import javax.swing.text.BadLocationException;

/**
 * The panel's log: the Environment's and the robots' output lines, and what each request got as
 * answer. Any thread may add a line; the oldest are dropped past {@link #MAX_LINES}, so that a long
 * run cannot fill the memory.
 */
public final class LogPane extends JPanel {
    private static final long serialVersionUID = 1L;
    /** The most lines kept. */
    public static final int MAX_LINES = 5000;

    private final JTextArea text = new JTextArea(8, 80);

    /** An empty log. */
    public LogPane() {
        super(new BorderLayout());
        text.setEditable(false);
        text.setName("log");
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        add(new JScrollPane(text), BorderLayout.CENTER);
    }

    /**
     * Adds a line, from any thread.
     *
     * @param line the line
     */
    public void append(String line) {
        SwingUtilities.invokeLater(() -> {
            text.append(line + "\n");
            int over = text.getLineCount() - 1 - MAX_LINES;
            if (over > 0) {
                try {
                    text.replaceRange("", 0, text.getLineEndOffset(over - 1));
                } catch (BadLocationException e) {
                    throw new IllegalStateException("the log's first " + over + " lines cannot be cut", e);
                }
            }
            text.setCaretPosition(text.getDocument().getLength());
        });
    }

    /** @return the log's text (on the event thread) */
    public String text() {
        return text.getText();
    }
}
