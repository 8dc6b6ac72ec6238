package robosim.bench;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robosim.protocol.Command;
import robosim.protocol.FrameException;
import robosim.protocol.Message;
import robosim.protocol.MessageCodec;
import robosim.protocol.RobotRequests;
import robosim.protocol.RobotState;
import robosim.protocol.TimeStep;
import robosim.protocol.Snapshot;
import robosim.protocol.SonarReading;

/**
 * The wire formats compared on the messages of every step: a robot's time step (state and 16
 * sonars), its requests (a velocity and a rotation), and a viewer snapshot of 100 robots. Every
 * format and message is warmed up first; each figure is the median of five trials.
 */
public final class CodecBench {
    private static final int TRIALS = 5;

    private CodecBench() {
    }

    /** One message in one format. */
    public record Result(String format, String message, int bytes, double encodeMicros, double decodeMicros) { }

    static List<Message> messages() {
        int[] sonar = {812, 1034, 2210, 5000, 5000, 3021, 1500, 700, 650, 900, 1200, 5000, 4000, 2222, 1111, 999};
        RobotState state = new RobotState(1234, 123_400, 2041.53, 7012.25, -37.5, 300, 12.5, 293.4, 306.6, false, 0)
                .with(SonarReading.PART, new SonarReading(sonar));
        List<Snapshot.RobotView> views = new ArrayList<>();
        for (int k = 0; k < 100; k++) {
            views.add(new Snapshot.RobotView("b" + k, 1000.5 + k, 2000.25 + k, k - 50.5, false, true, sonar));
        }
        return List.of(new TimeStep(1235, 123_400, state),
                new RobotRequests(1235, List.of(new Command.SetVel(300), new Command.SetRotVel(0))),
                new Snapshot(1234, 123_400, views));
    }

    /**
     * Measures every message in both formats.
     *
     * @param rounds encodings and decodings per measurement
     * @return the figures
     * @throws FrameException never, for well-formed messages
     */
    public static List<Result> run(int rounds) throws FrameException {
        List<MessageCodec> codecs = List.of(new MessageCodec(MessageCodec.Format.SMILE),
                new MessageCodec(MessageCodec.Format.JSON));
        for (int warm = 0; warm < 3; warm++) { // every pair warmed before any is measured
            for (MessageCodec codec : codecs) {
                for (Message m : messages()) {
                    for (int i = 0; i < rounds; i++) {
                        codec.decode(codec.encode(m));
                    }
                }
            }
        }
        List<Result> out = new ArrayList<>();
        for (int f = 0; f < codecs.size(); f++) {
            MessageCodec codec = codecs.get(f);
            for (Message m : messages()) {
                byte[] bytes = codec.encode(m);
                double[] enc = new double[TRIALS];
                double[] dec = new double[TRIALS];
                for (int t = 0; t < TRIALS; t++) {
                    long t0 = System.nanoTime();
                    for (int i = 0; i < rounds; i++) {
                        bytes = codec.encode(m);
                    }
                    long t1 = System.nanoTime();
                    for (int i = 0; i < rounds; i++) {
                        codec.decode(bytes);
                    }
                    long t2 = System.nanoTime();
                    enc[t] = (t1 - t0) / 1e3 / rounds;
                    dec[t] = (t2 - t1) / 1e3 / rounds;
                }
                out.add(new Result(MessageCodec.Format.values()[f].name(), m.getClass().getSimpleName(),
                        bytes.length, median(enc), median(dec)));
            }
        }
        return out;
    }

    static double median(double[] values) {
        double[] v = values.clone();
        java.util.Arrays.sort(v);
        return v[v.length / 2];
    }

    /**
     * Prints the figures, one line each.
     *
     * @param out     where
     * @param results the figures
     */
    public static void print(PrintWriter out, List<Result> results) {
        for (Result r : results) {
            out.printf(Locale.ROOT, "codec: %-5s %-14s %6d bytes  encode %7.2f us  decode %7.2f us%n",
                    r.format(), r.message(), r.bytes(), r.encodeMicros(), r.decodeMicros());
        }
        out.flush();
    }
}
