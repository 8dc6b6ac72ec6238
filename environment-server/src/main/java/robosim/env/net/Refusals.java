package robosim.env.net;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The robots refused while a run waits for its robots, by name, with why: the Environment's waiting
 * line names them, so that a user whose robots were turned away learns it there instead of waiting
 * out the connect timeout. A robot that connects later leaves the list. Names come from the wire, so
 * the list keeps only the latest {@link #MAX} of them.
 */
final class Refusals {
    /** The most refusals kept. */
    static final int MAX = 16;

    private final LinkedHashMap<String, String> byWho = new LinkedHashMap<>(16, 0.75f, false) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(Map.Entry<String, String> eldest) {
            return size() > MAX;
        }
    };

    /**
     * @param who    the robot's name (printable), or how a shared link is known
     * @param reason the Environment's reason, whose first clause is kept
     */
    void refused(String who, String reason) {
        byWho.remove(who);
        byWho.put(who, shortReason(who, reason));
    }

    /**
     * @param client how a shared link's client calls itself (its process, {@code pid 1234})
     * @return how a shared link of that client is listed: its robots are not named until it is admitted
     */
    static String linkOf(String client) {
        return LINK + " (" + client + ")";
    }

    /** How the refusals of shared links begin. */
    static final String LINK = "a shared link";

    /** @param who a robot that connected, or a link admitted: it is no longer refused */
    void admitted(String who) {
        byWho.remove(who);
    }

    /** Forgets them all: a new run waits for its robots. */
    void clear() {
        byWho.clear();
    }

    /** @return the refusals, oldest first */
    Map<String, String> all() {
        return new LinkedHashMap<>(byWho);
    }

    /**
     * The reason without the robot's own name in front and without the advice after its first
     * clause: {@code presented no run secret} of {@code robot r1 presented no run secret; this ...}.
     */
    static String shortReason(String who, String reason) {
        String r = reason;
        for (String prefix : new String[] {"robot " + who + " ", "robot " + who + "'s ", who + " ", LINK + " "}) {
            if (r.startsWith(prefix)) {
                r = r.substring(prefix.length());
                break;
            }
        }
        int semicolon = r.indexOf(';');
        return semicolon > 0 ? r.substring(0, semicolon) : r;
    }
}
