package robosim.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/** The fingerprint that ties a results folder to the experiment file that made it. */
public final class ExperimentFiles {
    private ExperimentFiles() {
    }

    /**
     * @param file the experiment file
     * @return the first 16 hex digits of the SHA-256 of its bytes
     * @throws IOException if it cannot be read
     */
    public static String fingerprint(Path file) throws IOException {
        return fingerprint(Files.readAllBytes(file));
    }

    /**
     * @param text a text
     * @return the first 16 hex digits of the SHA-256 of its UTF-8 bytes
     */
    static String fingerprint(String text) {
        return fingerprint(text.getBytes(java.nio.charset.StandardCharsets.UTF_8));
    }

    private static String fingerprint(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes), 0, 8);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("this JDK has no SHA-256", e);
        }
    }
}
