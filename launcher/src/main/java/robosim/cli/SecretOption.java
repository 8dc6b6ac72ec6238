package robosim.cli;

import picocli.CommandLine.Option;
import robosim.protocol.RunSecret;

/** The run secret a client command presents: shared by {@code robot}, {@code viewer} and {@code comms}. */
final class SecretOption {
    @Option(names = "--token", paramLabel = "SECRET", description = OptionTexts.TOKEN + "; the one env printed; default: $"
            + RunSecret.ENV + ", then the file $" + RunSecret.FILE_ENV + " names, then the file env wrote for the port"
            + " (~/.robosim/tokens/PORT). On a shared machine prefer the variable or the file: others can read a"
            + " command line")
    String token;

    /**
     * Makes the secret given on the command line the one this JVM's robots, viewers and control
     * clients present (through the system property {@value RunSecret#PROPERTY}).
     *
     * @return null, or what is wrong with the secret given
     */
    String apply() {
        if (token == null) {
            return null;
        }
        try {
            System.setProperty(RunSecret.PROPERTY, RunSecret.check(token));
            return null;
        } catch (IllegalArgumentException e) {
            return "--token: " + e.getMessage();
        }
    }
}
