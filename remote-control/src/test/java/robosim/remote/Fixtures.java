package robosim.remote;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.RobotParameters;
import robosim.protocol.SonarUnit;

/** Literal robots and a target that records what it is sent. */
final class Fixtures {
    private Fixtures() {
    }

    /** A round robot of radius 250 mm with two sonars (front, left) and a laser 20 mm ahead of its centre. */
    static RobotParameters robot(double maxVel, double maxRotVel) {
        return new RobotParameters("Pioneer", "test", 250, 400, 200, 200, maxVel, maxRotVel, 300, 300, 100, 100,
                0.0056, 5000, List.of(new SonarUnit(0, 100, 0, 0), new SonarUnit(1, 0, 100, 90)),
                20, 0, 0, 8000, RobotParameters.ROUND);
    }

    /** A target that writes each call as a line. */
    static class Recorder implements DriveTarget {
        final List<String> calls = new ArrayList<>();
        private final RobotParameters parameters;

        Recorder(RobotParameters parameters) {
            this.parameters = parameters;
        }

        @Override
        public String name() {
            return "r1";
        }

        @Override
        public RobotParameters parameters() {
            return parameters;
        }

        @Override
        public void drive(double vel, double rotVel) {
            calls.add("drive " + (int) vel + " " + (int) rotVel);
        }

        @Override
        public void stop() {
            calls.add("stop");
        }

        @Override
        public void move(double distance) {
            calls.add("move " + distance);
        }

        @Override
        public void setHeading(double heading) {
            calls.add("heading " + heading);
        }

        @Override
        public void sonar(boolean on) {
            calls.add("sonar " + on);
        }

        @Override
        public String laser(boolean on) {
            calls.add("laser " + on);
            return null;
        }

        @Override
        public String heat(boolean on) {
            calls.add("heat " + on);
            return on ? "no heat sensor here" : null;
        }

        @Override
        public void send(MessageDraft message) {
            calls.add("send " + message.recipient() + ": " + message.text());
        }
    }
}
