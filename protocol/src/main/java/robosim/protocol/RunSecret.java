package robosim.protocol;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.Map;
import java.util.Properties;
import java.util.regex.Pattern;

/**
 * The run secret: a random token the Environment makes (or is given) for one run, which robots,
 * viewers and control clients present in their hello. Without it a connection is refused, so that
 * only those the user gave the secret to can join, watch or change the run.
 *
 * <p>A client finds the secret in this order: an explicit value (a {@code --token} option, or the
 * system property {@value #PROPERTY}); the environment variable {@value #ENV}; the file the
 * environment variable {@value #FILE_ENV} names; the file the Environment wrote for the port the
 * client connects to on this machine (a loopback host), {@code ~/.robosim/tokens/PORT} (the folder
 * may be moved with the system property {@value #DIR_PROPERTY} or the environment variable
 * {@value #DIR_ENV}). So a robot program
 * on the Environment's machine, run by the same user, needs nothing at all.
 */
public final class RunSecret {
    /** The system property that holds the secret; {@code ArRobot} and the viewers read it. */
    public static final String PROPERTY = "robosim.token";
    /** The environment variable that holds the secret. */
    public static final String ENV = "ROBOSIM_TOKEN";
    /** The environment variable that names a file holding the secret. */
    public static final String FILE_ENV = "ROBOSIM_TOKEN_FILE";
    /** The system property that names the folder of the Environment's secret files. */
    public static final String DIR_PROPERTY = "robosim.tokenDir";
    /** The environment variable that names the folder of the Environment's secret files. */
    public static final String DIR_ENV = "ROBOSIM_TOKEN_DIR";
    /** What a secret may be: 16 to 128 letters, digits, '-' or '_'. */
    public static final Pattern RULE = Pattern.compile("[A-Za-z0-9_-]{16,128}");
    /** {@link #RULE} in words. */
    public static final String RULE_TEXT = "a run secret is 16 to 128 letters, digits, '-' or '_'";

    /** How the Environment's refusal of a peer that presented no secret goes on after the peer's name. */
    public static final String REFUSED_NONE = "presented no run secret";
    /** How the Environment's refusal of a peer that presented another secret goes on after the peer's name. */
    public static final String REFUSED_WRONG = "presented a wrong run secret";

    private static final SecureRandom RANDOM = new SecureRandom();

    private RunSecret() {
    }

    /** @return a new secret: 32 random bytes, 43 characters of URL-safe base64 */
    public static String create() {
        byte[] bytes = new byte[32];
        RANDOM.nextBytes(bytes);
        return Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
    }

    /**
     * @param secret a secret given by a user
     * @return it
     * @throws IllegalArgumentException if it breaks {@link #RULE_TEXT} (the value is not repeated)
     */
    public static String check(String secret) {
        if (secret == null || !RULE.matcher(secret).matches()) {
            throw new IllegalArgumentException("the run secret given (" + (secret == null ? 0 : secret.length())
                    + " characters) breaks the rule: " + RULE_TEXT);
        }
        return secret;
    }

    /**
     * Compares in time that does not depend on where the two differ.
     *
     * @param expected  the run's secret
     * @param presented what a peer presented, or null
     * @return whether they are the same
     */
    public static boolean matches(String expected, String presented) {
        if (expected == null || presented == null) {
            return false;
        }
        return MessageDigest.isEqual(expected.getBytes(StandardCharsets.UTF_8),
                presented.getBytes(StandardCharsets.UTF_8));
    }

    /**
     * Whether the Environment refused a peer for the secret it presented: such a refusal may clear
     * when the secret the client finds now is another (the Environment wrote its file after the
     * client looked, or replaced a file an earlier run left), see {@link #mayClear}.
     *
     * @param reason the reason of the Environment's refusal, with or without {@link Bye#REFUSED}
     * @return whether it is about the secret
     */
    public static boolean isSecretRefusal(String reason) {
        return reason != null && (reason.contains(REFUSED_NONE) || reason.contains(REFUSED_WRONG));
    }

    /**
     * The rule every client of the Environment follows when it is refused: a refusal for the secret
     * clears when the secret found now (in the places {@link #find} looks) is not the one presented;
     * any other refusal, or the same secret refused again, is final.
     *
     * @param reason    the Environment's reason
     * @param presented the secret the refused hello presented, or null
     * @param now       the secret found now, or null
     * @return whether to try again with {@code now}
     */
    public static boolean mayClear(String reason, String presented, String now) {
        return isSecretRefusal(reason) && now != null && !now.equals(presented);
    }

    /**
     * Finds the secret again after a refusal, as {@link #find(String, String, int)} does, but never
     * throws: a secret that cannot be read now is taken as none.
     *
     * @param host the host the client connects to
     * @param port the port it connects to
     * @return the secret found now, or null
     */
    public static String findAgain(String host, int port) {
        try {
            return find(null, host, port);
        } catch (IllegalArgumentException e) {
            return null;
        }
    }

    /** @return the folder of the Environment's secret files */
    public static Path folder() {
        return folder(System.getProperties(), System.getenv());
    }

    static Path folder(Properties properties, Map<String, String> env) {
        String dir = properties.getProperty(DIR_PROPERTY, env.get(DIR_ENV));
        if (dir != null && !dir.isBlank()) {
            return Path.of(dir);
        }
        return Path.of(properties.getProperty("user.home", "."), ".robosim", "tokens");
    }

    /**
     * @param port a port the Environment listens on
     * @return the file it writes the secret to for that port, in {@link #folder()}
     */
    public static Path fileFor(int port) {
        return folder().resolve(Integer.toString(port));
    }

    /**
     * Writes a secret to a file only its owner can read (where the file system knows owners),
     * making the folder (readable only by its owner) if it is missing; the file is replaced whole.
     *
     * @param file   the file
     * @param secret the secret
     * @throws IOException if it cannot be written
     */
    public static void write(Path file, String secret) throws IOException {
        Path dir = file.toAbsolutePath().getParent();
        boolean posix = dir.getFileSystem().supportedFileAttributeViews().contains("posix");
        if (!Files.isDirectory(dir)) {
            if (posix) {
                Files.createDirectories(dir, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
            } else {
                Files.createDirectories(dir);
            }
        }
        Path tmp = posix
                ? Files.createTempFile(dir, ".secret", ".tmp", PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")))
                : Files.createTempFile(dir, ".secret", ".tmp");
        try {
            Files.writeString(tmp, secret + "\n");
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /**
     * Finds the secret a client presents to the Environment at a port, in the order of this class's
     * description.
     *
     * @param explicit a value given on the command line, or null
     * @param host     the host the client connects to: the file the Environment wrote for a port is
     *                 read only for a loopback host, so a secret of this machine never goes elsewhere
     * @param port     the port the client connects to
     * @return the secret, or null if there is none (an Environment without a secret needs none)
     * @throws IllegalArgumentException if a secret found breaks {@link #RULE_TEXT}, or the file
     *                                  {@value #FILE_ENV} names cannot be read; the message says where it came from
     */
    public static String find(String explicit, String host, int port) {
        return find(explicit, isLoopback(host) ? port : -1, System.getProperties(), System.getenv());
    }

    /**
     * @param host a host name or address
     * @return whether it names this machine's loopback interface (a name that cannot be resolved does not)
     */
    static boolean isLoopback(String host) {
        try {
            return InetAddress.getByName(host).isLoopbackAddress();
        } catch (UnknownHostException | SecurityException e) {
            return false;
        }
    }

    /** @param port the port, or -1 for a host that is not this machine's loopback: no port's file is read */
    static String find(String explicit, int port, Properties properties, Map<String, String> env) {
        if (explicit != null) {
            return checked(explicit, "the --token option");
        }
        String property = properties.getProperty(PROPERTY);
        if (property != null && !property.isBlank()) {
            return checked(property, "the system property " + PROPERTY);
        }
        String variable = env.get(ENV);
        if (variable != null && !variable.isBlank()) {
            return checked(variable, "the environment variable " + ENV);
        }
        String named = env.get(FILE_ENV);
        if (named != null && !named.isBlank()) {
            return read(Path.of(named), "the file " + named + " (named by " + FILE_ENV + ")", true);
        }
        if (port < 0) {
            return null;
        }
        Path file = folder(properties, env).resolve(Integer.toString(port));
        return Files.isRegularFile(file) ? read(file, "the file " + file, false) : null;
    }

    private static String read(Path file, String where, boolean required) {
        try {
            return checked(Files.readString(file).strip(), where);
        } catch (IOException e) {
            if (!required) {
                return null;
            }
            throw new IllegalArgumentException("cannot read the run secret from " + where + ": " + e.getMessage(), e);
        }
    }

    private static String checked(String secret, String where) {
        if (!RULE.matcher(secret).matches()) {
            throw new IllegalArgumentException("the run secret from " + where + " breaks the rule: " + RULE_TEXT);
        }
        return secret;
    }

    /**
     * How a secret appears wherever a message is printed: never itself.
     *
     * @param secret a secret, or null
     * @return {@code (none)} or {@code (secret)}
     */
    static String masked(String secret) {
        return secret == null ? "(none)" : "(secret)";
    }
}
