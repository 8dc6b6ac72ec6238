package robosim.hw;

/**
 * What a {@link RobotRuntime} chooses for its robots: how they reach the Environment, and what kind
 * of thread reads their links. The default runtime takes them from the system properties when it is
 * made ({@link #fromSystemProperties()}); a runtime made with {@link RobotRuntime#create(String,
 * RuntimeChoices)} takes them as given, whatever the properties say.
 *
 * @param links          a connection per robot, one for all, or the first alone and the others
 *                       sharing one (see {@link EnvironmentLinks})
 * @param pioneer        a Pioneer robot server, {@code host:port}, that every robot of the runtime
 *                       drives instead of the Environment it is given (see {@link PioneerLink}); null
 *                       for the Environment itself
 * @param virtualThreads whether the links' threads are virtual where the JDK allows it (JDK 24 and
 *                       newer, see {@link RobotThreads}); platform threads otherwise
 */
public record RuntimeChoices(EnvironmentLinks.Mode links, String pioneer, boolean virtualThreads) {
    /**
     * Checks the values.
     *
     * @throws IllegalArgumentException if {@code links} is null
     */
    public RuntimeChoices {
        if (links == null) {
            throw new IllegalArgumentException("null was supplied for links: it is auto, own or shared");
        }
        if (pioneer != null && pioneer.isBlank()) {
            pioneer = null;
        }
    }

    /** @return links chosen by the robots' count ({@code auto}), the Environment itself, virtual threads where the JDK allows */
    public static RuntimeChoices defaults() {
        return new RuntimeChoices(EnvironmentLinks.Mode.AUTO, null, true);
    }

    /**
     * @return what the system properties say now: {@value EnvironmentLinks#PROPERTY} (the links),
     *         {@value EnvironmentLinks#PIONEER_PROPERTY} (a Pioneer robot server) and
     *         {@value RobotThreads#PROPERTY} ({@code platform} keeps platform threads)
     * @throws IllegalArgumentException if {@value EnvironmentLinks#PROPERTY} names no mode
     */
    public static RuntimeChoices fromSystemProperties() {
        return new RuntimeChoices(EnvironmentLinks.Mode.configured(),
                System.getProperty(EnvironmentLinks.PIONEER_PROPERTY), !RobotThreads.platformConfigured());
    }

    /** @param mode the links to choose @return these choices with those links */
    public RuntimeChoices withLinks(EnvironmentLinks.Mode mode) {
        return new RuntimeChoices(mode, pioneer, virtualThreads);
    }

    /** @param address a Pioneer robot server, {@code host:port}, or null @return these choices with it */
    public RuntimeChoices withPioneer(String address) {
        return new RuntimeChoices(links, address, virtualThreads);
    }

    /** @param virtual whether link threads are virtual where the JDK allows @return these choices with that */
    public RuntimeChoices withVirtualThreads(boolean virtual) {
        return new RuntimeChoices(links, pioneer, virtual);
    }
}
