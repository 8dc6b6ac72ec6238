package robosim.protocol;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Supplier;

/**
 * Random valid messages of every type, for the codec's round-trip property and the fuzz tests'
 * seeds: numbers at their edges (NaN, infinities, -0, the extremes) wherever a record allows them,
 * text from all of Unicode (valid text: no lone surrogates), empty and long lists.
 */
public final class RandomMessages {
    private static final double[] EDGE_DOUBLES = {0.0, -0.0, 1, -1, Double.NaN, Double.POSITIVE_INFINITY,
        Double.NEGATIVE_INFINITY, Double.MAX_VALUE, -Double.MAX_VALUE, Double.MIN_VALUE, 1e-300, 0.1, 1e15 + 0.5};
    private static final long[] EDGE_LONGS = {0, 1, -1, Long.MAX_VALUE, Long.MIN_VALUE, Integer.MAX_VALUE,
        Integer.MAX_VALUE + 1L, Integer.MIN_VALUE};

    private final Random random;

    /** @param random where the values come from */
    public RandomMessages(Random random) {
        this.random = random;
    }

    /** @return a message of a random type */
    public Message any() {
        return switch (random.nextInt(16)) {
            case 0 -> new RobotHello(text(), text(), nullOr(this::parameters));
            case 1 -> new Welcome(text(), (int) anyLong(), nullOr(this::state), properties(), anyLong());
            case 2 -> new TimeStep(anyLong(), anyLong(), nullOr(this::state));
            case 3 -> new RobotRequests(anyLong(), commands());
            case 4 -> new ViewerHello(text());
            case 5 -> world();
            case 6 -> snapshot();
            case 7 -> new Bye(text(), text());
            case 8 -> new CommsUpdate(nullOr(this::anyDouble), nullOr(random::nextBoolean),
                    nullOr(() -> (int) anyLong()), nullOr(this::anyDouble), nullOr(() -> (int) anyLong()));
            case 9 -> new LinkHello(text());
            case 10 -> new TimeSteps(anyLong(), anyLong(),
                    list(() -> new TimeSteps.ForRobot(text(), nullOr(this::state)), 4));
            case 12 -> new ControlRequest(anyLong(), text(), list(() -> text(40), ControlRequest.MAX_ARGS));
            case 13 -> new ControlReply(anyLong(), random.nextBoolean(), text());
            case 14 -> runStatus();
            case 15 -> new LogLine(Math.abs(random.nextLong() / 2), new String[] {"SEVERE", "WARNING", "INFO"}[random.nextInt(3)],
                    text());
            default -> new LinkRequests(anyLong(), list(() -> new LinkRequests.ForRobot(text(), commands()), 4));
        };
    }

    /** @return a run status of random robots, every value within its rule */
    public RunStatus runStatus() {
        return new RunStatus(anyLong(), text(), Math.abs(random.nextLong() / 2), random.nextInt(1 << 30),
                random.nextBoolean(), random.nextBoolean() ? 0 : 1000 * random.nextDouble(),
                list(() -> new RunStatus.RobotStatus(text(40), text(10), text(), random.nextBoolean(), finite(),
                        finite(), finite(), finite(), finite(), random.nextBoolean(), random.nextInt(1000),
                        random.nextInt(1 << 20), random.nextInt(1 << 20), random.nextInt(1 << 20)), 4));
    }

    /** @return a world of random obstacles, robots and heat sources */
    public WorldDescription world() {
        return new WorldDescription(text(), anyDouble(), anyDouble(), (int) anyLong(),
                list(() -> new WorldDescription.Obstacle(doubles(12), anyDouble()), 5),
                list(() -> new WorldDescription.RobotInfo(text(), text(), nullOr(this::parameters)), 3),
                list(() -> new WorldDescription.HeatSource(anyDouble(), anyDouble(), anyDouble()), 3));
    }

    /** @return a snapshot of random robots, messages and speech */
    public Snapshot snapshot() {
        return new Snapshot(anyLong(), anyLong(), list(this::view, 4), list(this::delivery, 3),
                list(() -> new Snapshot.Said(text(), text()), 2));
    }

    private Snapshot.RobotView view() {
        return new Snapshot.RobotView(text(), anyDouble(), anyDouble(), anyDouble(), random.nextBoolean(),
                random.nextBoolean(), ints(32), anyDouble(), anyDouble(), anyDouble(), ints(400), anyDouble(),
                anyDouble(), anyDouble());
    }

    /** @return up to 4 world properties, each name and value within its rule */
    private Map<String, String> properties() {
        Map<String, String> p = new LinkedHashMap<>();
        for (int n = random.nextInt(5); n > 0; n--) {
            p.put("p" + Integer.toString(random.nextInt(1 << 20), 36), text(100));
        }
        return p;
    }

    RobotParameters parameters() {
        return new RobotParameters(text(), text(), anyDouble(), anyDouble(), anyDouble(), anyDouble(), anyDouble(),
                anyDouble(), anyDouble(), anyDouble(), anyDouble(), anyDouble(), anyDouble(), anyDouble(),
                list(() -> new SonarUnit((int) anyLong(), anyDouble(), anyDouble(), anyDouble()), 20),
                anyDouble(), anyDouble(), anyDouble(), anyDouble(), random.nextBoolean() ? text() : null);
    }

    RobotState state() {
        return new RobotState(anyLong(), anyLong(), anyDouble(), anyDouble(), anyDouble(), anyDouble(), anyDouble(),
                anyDouble(), anyDouble(), random.nextBoolean(), (int) anyLong(), list(this::delivery, 3),
                list(() -> text(80), 2), nullOr(random::nextBoolean), StateParts.NONE)
                .with(SonarReading.PART, nullOr(() -> new SonarReading(someInts(32), nullOr(random::nextLong))))
                .with(LaserReading.PART, nullOr(() -> new LaserReading(someInts(400))))
                .with(HeatReading.PART, nullOr(() -> new HeatReading(anyDouble(), anyDouble(), anyDouble())))
                .with(Bumpers.PART, nullOr(() -> new Bumpers(random.nextInt(1 << Bumpers.SECTORS))))
                .with(TruePose.PART, nullOr(() -> new TruePose(anyDouble(), anyDouble(), anyDouble())))
                .with(BatteryReading.PART, nullOr(() -> new BatteryReading(random.nextDouble() * 99,
                        random.nextDouble() * 100)));
    }

    private MessageDelivery delivery() {
        Command.Addressing[] modes = Command.Addressing.values();
        return new MessageDelivery(text(), nullOr(() -> modes[random.nextInt(modes.length)]), text(), text(), text(),
                anyLong(), anyLong());
    }

    /** @return up to 30 commands, each valid by its record's rules */
    public List<Command> commands() {
        return list(this::command, 30);
    }

    Command command() {
        return switch (random.nextInt(31)) {
            case 0 -> new Command.SetVel(finite());
            case 1 -> new Command.SetRotVel(finite());
            case 2 -> new Command.SetVel2(finite(), finite());
            case 3 -> new Command.Move(finite());
            case 4 -> new Command.SetHeading(finite());
            case 5 -> new Command.SetDeltaHeading(finite());
            case 6 -> new Command.Stop();
            case 7 -> new Command.SetMaxTransVel(finite());
            case 8 -> new Command.SetMaxRotVel(finite());
            case 9 -> new Command.SetSonar(random.nextBoolean());
            case 10 -> new Command.ConfigureLaser(random.nextBoolean(), random.nextBoolean() ? 1 : 0.5, positive());
            case 11 -> new Command.ConfigureHeatSensor(random.nextBoolean(), 360 * (1 - random.nextDouble()),
                    positive());
            case 12 -> {
                Command.Addressing mode = Command.Addressing.values()[random.nextInt(3)];
                yield new Command.SendMessage(anyLong(), mode, mode == Command.Addressing.ALL ? text() : "to" + text(40),
                        text(40), text(200));
            }
            case 13 -> new Command.JoinGroup("g" + text(40));
            case 14 -> new Command.LeaveGroup("g" + text(40));
            case 15 -> new Command.ReportFound("o" + text(40));
            case 16 -> new Command.Say(text(1000));
            case 17 -> new Command.MoveWheels(finite(), finite());
            case 18 -> new Command.SetDriveLimit(Command.DriveLimit.values()[random.nextInt(4)], positive());
            case 19 -> new Command.SetTruePose(finite(), finite(), finite());
            case 20 -> new Command.ResetToStart();
            case 21 -> new Command.ReportTruePose(random.nextBoolean());
            case 23 -> new Command.ConfigurePtz(PtzModel.values()[random.nextInt(2)], positive());
            case 24 -> new Command.AimPtz(finite(), finite(), (int) anyLong());
            case 25 -> new Command.TrackColors(random.nextBoolean());
            case 26 -> new Command.BindChannel(1 + random.nextInt(CameraView.CHANNELS),
                    random.nextBoolean() ? null : Colors.format(random.nextInt(0x1000000)));
            case 27 -> new Command.SetSonarCycle(random.nextInt(Command.SetSonarCycle.MAX_SONAR_CYCLE_MS + 1));
            case 28 -> new Command.SetMotors(random.nextBoolean());
            case 29 -> new Command.ReportMetric("m" + Integer.toString(random.nextInt(1 << 20), 36), finite());
            case 30 -> new Command.EndRun("r" + text(100).replaceAll("\\p{Cc}", "_"));
            default -> new Command.SetAccel(positive(), positive());
        };
    }

    private <T> T nullOr(Supplier<T> value) {
        return random.nextInt(8) == 0 ? null : value.get();
    }

    private <T> List<T> list(Supplier<T> element, int max) {
        int n = random.nextInt(4) == 0 ? 0 : random.nextInt(max + 1);
        List<T> l = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            l.add(element.get());
        }
        return l;
    }

    private int[] someInts(int max) {
        int[] v = ints(max);
        return v == null ? new int[0] : v;
    }

    private int[] ints(int max) {
        if (random.nextInt(10) == 0) {
            return null;
        }
        int[] v = new int[random.nextInt(max + 1)];
        for (int i = 0; i < v.length; i++) {
            v[i] = random.nextInt(4) == 0 ? (int) anyLong() : random.nextInt(10_000);
        }
        return v;
    }

    private double[] doubles(int max) {
        double[] v = new double[random.nextInt(max + 1)];
        for (int i = 0; i < v.length; i++) {
            v[i] = anyDouble();
        }
        return v;
    }

    double anyDouble() {
        return switch (random.nextInt(4)) {
            case 0 -> EDGE_DOUBLES[random.nextInt(EDGE_DOUBLES.length)];
            case 1 -> Double.longBitsToDouble(random.nextLong());
            default -> (random.nextDouble() - 0.5) * 20_000;
        };
    }

    private double finite() {
        double d = anyDouble();
        return Double.isFinite(d) ? d : random.nextGaussian();
    }

    private double positive() {
        double d = Math.abs(finite());
        return d > 0 ? d : 1;
    }

    long anyLong() {
        return random.nextBoolean() ? EDGE_LONGS[random.nextInt(EDGE_LONGS.length)] : random.nextLong();
    }

    /** @return text of up to 40 characters, or now and then null */
    String text() {
        return random.nextInt(10) == 0 ? null : text(40);
    }

    /**
     * @param max the most characters
     * @return text of up to {@code max} characters from all of Unicode (control characters too),
     *         none a lone surrogate
     */
    public String text(int max) {
        int n = random.nextInt(max + 1);
        StringBuilder b = new StringBuilder(n);
        while (b.length() < n) {
            int cp = switch (random.nextInt(4)) {
                case 0 -> 0x20 + random.nextInt(0x5f);
                case 1 -> random.nextInt(0x20);
                case 2 -> random.nextBoolean() ? random.nextInt(0xd800) : 0xe000 + random.nextInt(0x2000);
                default -> 0x10000 + random.nextInt(0x100000);
            };
            if (b.length() + Character.charCount(cp) <= n) {
                b.appendCodePoint(cp);
            } else {
                b.append('x');
            }
        }
        return b.toString();
    }
}
