package robosim.hw;

import java.util.Map;
import java.util.OptionalDouble;
import robosim.protocol.RobotHello;
import robosim.protocol.Welcome;

/**
 * What a robot learnt of the world and the run in its {@link Welcome}: the world's properties and the
 * run's seed, with the reading of a property as a number.
 *
 * @param robot      the robot's name, for messages
 * @param properties the world's properties, name to value
 * @param seed       the run's seed
 */
record WelcomeFacts(String robot, Map<String, String> properties, long seed) {
    /** Before a welcome: no properties, seed 0. */
    static WelcomeFacts none(String robot) {
        return new WelcomeFacts(robot, Map.of(), 0);
    }

    /** @return the facts the welcome gives */
    static WelcomeFacts of(String robot, Welcome welcome) {
        return new WelcomeFacts(robot, welcome.properties(), welcome.seed());
    }

    /**
     * @param name a property's name
     * @return its value as a finite number, or empty when the world does not give it
     * @throws IllegalStateException if the world gives it but not as a finite number
     */
    OptionalDouble number(String name) {
        String value = properties.get(name);
        if (value == null) {
            return OptionalDouble.empty();
        }
        String text = value.trim();
        double v;
        try {
            // Java's own forms of a number are refused: hex, a type suffix, NaN, Infinity
            v = text.matches("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?") ? Double.parseDouble(text) : Double.NaN;
        } catch (NumberFormatException e) {
            v = Double.NaN;
        }
        if (!Double.isFinite(v)) {
            throw new IllegalStateException("robot " + robot + ": the world's property " + name + " is "
                    + RobotHello.quoted(value) + ", not a number");
        }
        return OptionalDouble.of(v);
    }
}
