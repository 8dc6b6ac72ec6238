package robosim.hw;

import robosim.protocol.Bye;

/**
 * How a robot's part in a run ended, for its program to read (see
 * {@link AbstractRobot#getRunEnd()}) and for a launcher to report in one line ({@link #describe()}).
 *
 * @param robot       the robot's name
 * @param kind        how it ended
 * @param environment the Environment's host and port, {@code host:port}
 * @param step        the last step the Environment opened for the robot; 0 before the first
 * @param reason      why, in the words of whoever ended it
 */
public record RunEnd(String robot, Kind kind, String environment, long step, String reason) {
    /** How a robot's part in a run can end. */
    public enum Kind {
        /** The Environment ended the run: the step limit, the gold found, every robot gone. */
        RUN_ENDED(false),
        /** The robot's program left: it disconnected, or all its code ended. */
        LEFT(false),
        /** The robot never joined: no Environment answered, or the connection failed before a welcome. */
        NOT_CONNECTED(true),
        /** The Environment refused the robot's hello. */
        REFUSED(true),
        /** The Environment dropped the robot from the run: a broken rule, a missed step deadline. */
        DROPPED(true),
        /**
         * The Environment was lost: it closed the connection without a bye, the connection broke,
         * or it sent nothing, neither a step nor a keep-alive, for the lost time.
         */
        LOST(true);

        private final boolean failure;

        Kind(boolean failure) {
            this.failure = failure;
        }

        /** @return whether the robot's part ended by anything but the run's end or its own leave */
        public boolean isFailure() {
            return failure;
        }
    }

    /**
     * How a bye from the Environment ends a robot's part, as {@link Bye} defines its reasons.
     *
     * @param reason the bye's reason
     * @return the kind of end
     */
    static Kind ofBye(String reason) {
        if (reason.startsWith(Bye.DONE)) {
            return Kind.RUN_ENDED;
        }
        if (reason.startsWith(Bye.REFUSED)) {
            return Kind.REFUSED;
        }
        return reason.equals(Bye.GOODBYE) ? Kind.LEFT : Kind.DROPPED;
    }

    /**
     * @param reason a bye's reason from the Environment
     * @return the reason without the prefix that says its kind
     */
    static String withoutPrefix(String reason) {
        for (String prefix : new String[] {Bye.DONE, Bye.REFUSED}) {
            if (reason.startsWith(prefix)) {
                return reason.substring(prefix.length());
            }
        }
        return reason;
    }

    /**
     * @return one line naming the robot, what happened, the Environment, the last step and the
     *         reason, for example {@code robot r1 lost the Environment at 127.0.0.1:5000 after step
     *         42: it closed the connection without a bye}
     */
    public String describe() {
        String when = step > 0 ? "after step " + step : "before step 1";
        String what = switch (kind) {
            case RUN_ENDED -> "ran to the end of the run at " + environment;
            case LEFT -> "left the run at " + environment;
            case NOT_CONNECTED -> "could not join the run at " + environment;
            case REFUSED -> "was refused by the Environment at " + environment;
            case DROPPED -> "was dropped by the Environment at " + environment;
            case LOST -> "lost the Environment at " + environment;
        };
        return "robot " + robot + " " + what + " " + when + ": " + reason;
    }
}
