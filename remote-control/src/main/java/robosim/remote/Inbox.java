package robosim.remote;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

/**
 * The messages the robot received, newest last, for the window's list: the latest {@value #KEPT},
 * so a chatty team cannot grow the window without bound. Called from the robot's thread and the
 * window's, so every method is synchronized.
 */
public final class Inbox {
    /** How many messages it keeps. */
    public static final int KEPT = 200;

    private final Deque<String> lines = new ArrayDeque<>();
    private long total;

    /**
     * A message as the list shows it: {@code step 12, from r2 to all: hello}; an object sent as JSON
     * shows its class and its JSON.
     *
     * @param step the step it was sent in
     * @param from the sender
     * @param to   the robot or group it was addressed to, or {@code *} for everyone
     * @param kind {@code text}, or the class name of the object sent
     * @param body the text, or the object's JSON
     * @return the line
     */
    public static String line(long step, String from, String to, String kind, String body) {
        String recipient = "*".equals(to) ? "all" : to;
        String shown = "text".equals(kind) ? body : kind + " " + body;
        return "step " + step + ", from " + from + " to " + recipient + ": " + shown;
    }

    /** @param line a message received, as the list shows it */
    public synchronized void add(String line) {
        lines.addLast(line);
        total++;
        if (lines.size() > KEPT) {
            lines.removeFirst();
        }
    }

    /** @return the messages kept, oldest first */
    public synchronized List<String> lines() {
        return new ArrayList<>(lines);
    }

    /** @return how many messages came in all, kept or not */
    public synchronized long total() {
        return total;
    }
}
