package robosim.aria;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.ToDoubleBiFunction;
import java.util.function.ToDoubleFunction;

/**
 * The range devices attached to a robot, and ARIA's rule for asking them all at once
 * ({@code ArRobot::checkRangeDevicesCurrentPolar} and its kin in ArRobot.cpp): the smallest answer
 * over the devices, the first device on a tie, −1 when none is attached.
 */
final class RangeDevices {
    private final List<ArRangeDevice> devices = new CopyOnWriteArrayList<>();

    void add(ArRangeDevice device, ArRobot robot) {
        device.setRobot(robot);
        devices.add(device);
    }

    void remove(ArRangeDevice device) {
        if (devices.remove(device)) {
            device.setRobot(null);
        }
    }

    ArRangeDevice find(String name) {
        return devices.stream().filter(d -> d.getName().equals(name)).findFirst().orElse(null);
    }

    List<ArRangeDevice> list() {
        return List.copyOf(devices);
    }

    /** Moves every device's readings with the robot's frame (ARIA's {@code applyTransform}). */
    void applyTransform(ArTransform moved, boolean doCumulative) {
        for (ArRangeDevice d : devices) {
            d.applyTransform(moved, doCumulative);
        }
    }

    /**
     * Picks the device with the smallest answer, then asks it again to fill the out-parameter.
     *
     * @param ask        a device's answer without the out-parameter
     * @param askFilling the same question, filling {@code out}
     * @param out        null, or what the nearest device fills
     * @return the smallest answer, or −1 if no device is attached
     */
    <T> double nearest(ToDoubleFunction<ArRangeDevice> ask, ToDoubleBiFunction<ArRangeDevice, T> askFilling, T out) {
        ArRangeDevice best = null;
        double closest = 0;
        for (ArRangeDevice d : devices) {
            double dist = ask.applyAsDouble(d);
            // ARIA keeps the first device on a tie
            if (best == null || dist < closest) {
                best = d;
                closest = dist;
            }
        }
        if (best == null) {
            return -1;
        }
        if (out != null) {
            askFilling.applyAsDouble(best, out);
        }
        return closest;
    }
}
