package robosim.experiment;

import robosim.env.net.RunReport;

/** How a run ended, as the one word a results table gives it. */
final class Endings {
    private Endings() {
    }

    static String of(RunReport report) {
        String r = report.endReason();
        if (r.startsWith("gold found")) {
            return "gold-found";
        }
        if (r.startsWith("step limit") || r.startsWith("the world's step limit")) {
            return "step-limit";
        }
        if (r.startsWith("every robot has disconnected")) {
            return "all-gone";
        }
        return "other";
    }
}
