package robosim.env.net;

import robosim.protocol.RunSecret;

/**
 * Who may use an Environment's ports.
 *
 * @param secret     the run secret every robot, viewer and control client must present (see
 *                   {@link RunSecret}), or null for none: then anyone who can reach the ports may
 *                   join, watch and change the run, which the Environment allows on loopback only
 * @param publicView whether viewers may watch without the secret (they can never change the run)
 */
public record Access(String secret, boolean publicView) {
    /** Checks the secret against {@link RunSecret#RULE_TEXT}. */
    public Access {
        if (secret != null) {
            RunSecret.check(secret);
        }
    }

    /** @return no secret: for tests and tools on loopback */
    public static Access open() {
        return new Access(null, false);
    }

    /**
     * @param secret the run's secret
     * @return access for those who present it, viewers too
     */
    public static Access secret(String secret) {
        return new Access(secret, false);
    }

    /** @return whether a secret is needed at all */
    public boolean guarded() {
        return secret != null;
    }

    /**
     * What a hello's secret says.
     *
     * @param who       the peer, for the reason
     * @param presented the secret it presented, or null
     * @return why it is refused, or null if it may go on (always, when the run has no secret)
     */
    String refusal(String who, String presented) {
        if (!guarded() || RunSecret.matches(secret, presented)) {
            return null;
        }
        return who + " " + (presented == null ? RunSecret.REFUSED_NONE : RunSecret.REFUSED_WRONG)
                + "; this Environment admits only those who present the secret it printed at its start (a --token"
                + " option, the " + RunSecret.ENV + " variable, or the file it wrote)";
    }

    /** @return the secret masked, so that the record never prints it */
    @Override
    public String toString() {
        return "Access[secret=" + (secret == null ? "(none)" : "(secret)") + ", publicView=" + publicView + "]";
    }
}
