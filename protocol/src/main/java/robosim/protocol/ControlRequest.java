package robosim.protocol;

import java.util.List;

/**
 * A change to a running run, asked for by a control client (see {@link ControlHello}) on the viewer
 * port: pause, resume, step N, stop, pace X, move NAME X Y TH or remove NAME. The Environment checks
 * every value and answers each request with a {@link ControlReply} of the same id, confirming what it
 * did or saying why it refused; a refused request leaves the run as it was.
 *
 * <p>The arguments travel as the words a user typed, so that the Environment alone decides what a
 * valid value is and says so in one place (for example "step N: N must be a whole number from 1 to
 * 1000000, got 0").
 *
 * @param id   the client's number for the request, echoed in the reply
 * @param op   what to do: {@code pause}, {@code resume}, {@code step}, {@code stop}, {@code pace},
 *             {@code move} or {@code remove}
 * @param args the operation's arguments, in order; none when absent on the wire
 */
public record ControlRequest(long id, String op, List<String> args) implements Message {
    /** The most arguments a request may carry: more than any operation takes. */
    public static final int MAX_ARGS = 8;

    /**
     * Copies the arguments so the record stays immutable.
     *
     * @throws IllegalArgumentException if there are more than {@value #MAX_ARGS} arguments, or one is null
     */
    public ControlRequest {
        if (args == null) {
            args = List.of();
        }
        for (String a : args) {
            // List.copyOf would throw a NullPointerException, which the codec takes for a broken frame
            if (a == null) {
                throw new IllegalArgumentException("a control request's arguments are text, not null");
            }
        }
        args = List.copyOf(args);
        if (args.size() > MAX_ARGS) {
            throw new IllegalArgumentException("a control request carries at most " + MAX_ARGS + " arguments, got "
                    + args.size());
        }
    }
}
