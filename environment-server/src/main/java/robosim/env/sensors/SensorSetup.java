package robosim.env.sensors;

import java.util.random.RandomGenerator;
import robosim.env.world.Noise;
import robosim.protocol.RobotParameters;

/**
 * What a robot's sensor is made from.
 *
 * @param params the robot's parameters: its sonar ring, laser pose, ...
 * @param noise  the world's sensor noise
 * @param random the robot's own seeded stream, shared by its sensors and its odometry
 */
public record SensorSetup(RobotParameters params, Noise noise, RandomGenerator random) {
    /**
     * @param range a range read, mm
     * @param sigma the standard deviation of its noise, mm; 0 for none
     * @return the range with its noise drawn from the robot's stream
     */
    double noisy(double range, double sigma) {
        return sigma > 0 ? range + random.nextGaussian() * sigma : range;
    }
}
