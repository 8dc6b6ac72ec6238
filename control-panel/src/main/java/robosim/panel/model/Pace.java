package robosim.panel.model;

import java.util.List;

/**
 * The stops of the panel's pacing slider, slowest first: factors of real time, then as fast as
 * possible. A slider of stops rather than a continuous factor, because users pick "half speed" or
 * "ten times" and a continuous slider would flood the Environment with requests while dragged.
 *
 * @param word  the pace as the control request says it ({@code max}, {@code realtime} or a factor)
 * @param label the pace as the slider shows it
 */
public record Pace(String word, String label) {
    /** The stops, slowest first; {@link #REALTIME} and {@link #MAX} among them. */
    public static final List<Pace> STOPS = List.of(
            new Pace("0.1", "0.1x"), new Pace("0.25", "0.25x"), new Pace("0.5", "0.5x"),
            new Pace("realtime", "1x"), new Pace("2", "2x"), new Pace("5", "5x"), new Pace("10", "10x"),
            new Pace("100", "100x"), new Pace("max", "max"));
    /** The index of real time in {@link #STOPS}. */
    public static final int REALTIME = 3;
    /** The index of as fast as possible in {@link #STOPS}. */
    public static final int MAX = STOPS.size() - 1;

    /**
     * @param factor the pace a status reports: 0 for as fast as possible, else a factor of real time
     * @return the index of the stop nearest to it (on a log scale), so the slider shows the pace in force
     */
    public static int nearest(double factor) {
        if (factor <= 0) {
            return MAX;
        }
        int best = 0;
        double bestDistance = Double.MAX_VALUE;
        for (int i = 0; i < MAX; i++) {
            double stop = STOPS.get(i).word().equals("realtime") ? 1 : Double.parseDouble(STOPS.get(i).word());
            double d = Math.abs(Math.log(stop / factor));
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        return best;
    }
}
