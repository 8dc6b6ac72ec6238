package robosim.aria;

/**
 * ARIA's {@code ArDeviceConnection}: where a robot's commands and packets go. ARIA programs that
 * make their own connection give it to the robot ({@link ArRobot#setDeviceConnection}); the robot
 * then connects there when it connects. In RoboSim the robot's link reads and writes the packets
 * itself, so a device connection says where, and whether something answers there.
 */
public abstract class ArDeviceConnection {
    /** Never opened. */
    public static final int STATUS_NEVER_OPENED = 1;
    /** Open. */
    public static final int STATUS_OPEN = 2;
    /** Tried to open, and failed. */
    public static final int STATUS_OPEN_FAILED = 3;
    /** Closed by {@link #close()}. */
    public static final int STATUS_CLOSED_NORMALLY = 4;
    /** Closed by an error. */
    public static final int STATUS_CLOSED_ERROR = 5;

    /** The connection's state, one of the {@code STATUS_} values. */
    protected volatile int status = STATUS_NEVER_OPENED;
    private volatile String deviceName = "";

    /** @return the state: one of the {@code STATUS_} values */
    public int getStatus() {
        return status;
    }

    /** @param messageNumber a {@code STATUS_} value @return what it means, in ARIA's words */
    public String getStatusMessage(int messageNumber) {
        return switch (messageNumber) {
            case STATUS_NEVER_OPENED -> "Never opened";
            case STATUS_OPEN -> "Open";
            case STATUS_OPEN_FAILED -> "Open failed";
            case STATUS_CLOSED_NORMALLY -> "Closed";
            case STATUS_CLOSED_ERROR -> "Closed on error";
            default -> "Unknown status";
        };
    }

    /** @param messageNumber what {@code open} returned @return what it means */
    public abstract String getOpenMessage(int messageNumber);

    /** @return whether it opened */
    public abstract boolean openSimple();

    /** @return true once it is closed */
    public boolean close() {
        status = STATUS_CLOSED_NORMALLY;
        return true;
    }

    /** @return the port's name, as its kind names it */
    public abstract String getPortName();

    /** @return the kind of port */
    public abstract String getPortType();

    /** @param name a name for the device at the other end */
    public void setDeviceName(String name) {
        deviceName = name == null ? "" : name;
    }

    /** @return the device's name, "" unless set */
    public String getDeviceName() {
        return deviceName;
    }

    /** @return the host a robot given this connection connects to */
    abstract String host();

    /** @return the TCP port a robot given this connection connects to */
    abstract int port();
}
