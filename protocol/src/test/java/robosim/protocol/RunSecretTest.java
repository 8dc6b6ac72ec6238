package robosim.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Where a client finds the run secret, in order, and how the Environment's file is written. */
class RunSecretTest {
    private static final String A = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa";
    private static final String B = "bbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb";
    private static final String C = "ccccccccccccccccccccccccccccccccccccccccccc";
    private static final String D = "ddddddddddddddddddddddddddddddddddddddddddd";

    @TempDir
    Path dir;

    private Properties properties(String token) {
        Properties p = new Properties();
        p.setProperty("user.home", dir.resolve("home").toString());
        if (token != null) {
            p.setProperty(RunSecret.PROPERTY, token);
        }
        return p;
    }

    @Test
    void aNewSecretIsLongRandomAndFollowsTheRule() {
        String one = RunSecret.create();
        String two = RunSecret.create();

        assertEquals(43, one.length());
        assertTrue(RunSecret.RULE.matcher(one).matches());
        assertNotEquals(one, two);
    }

    @Test
    void theOptionComesFirstThenThePropertyThenTheVariableThenTheFiles() throws IOException {
        Path named = dir.resolve("named");
        Files.writeString(named, D + "\n");
        Path byPort = dir.resolve("home/.robosim/tokens/5000");
        RunSecret.write(byPort, "eeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeee");
        Map<String, String> env = Map.of(RunSecret.ENV, C, RunSecret.FILE_ENV, named.toString());

        assertEquals(A, RunSecret.find(A, 5000, properties(B), env));
        assertEquals(B, RunSecret.find(null, 5000, properties(B), env));
        assertEquals(C, RunSecret.find(null, 5000, properties(null), env));
        assertEquals(D, RunSecret.find(null, 5000, properties(null), Map.of(RunSecret.FILE_ENV, named.toString())));
        assertEquals("eeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeee", RunSecret.find(null, 5000, properties(null), Map.of()));
        assertNull(RunSecret.find(null, 5001, properties(null), Map.of()));
    }

    @Test
    void theFileForAPortIsReadOnlyForThisMachine() throws IOException {
        RunSecret.write(dir.resolve("tokens/5000"), A);
        System.setProperty(RunSecret.DIR_PROPERTY, dir.resolve("tokens").toString());
        try {
            assertEquals(A, RunSecret.find(null, "127.0.0.1", 5000));
            assertEquals(A, RunSecret.find(null, "localhost", 5000));
            // a secret of this machine never goes to another host at the same port
            assertNull(RunSecret.find(null, "192.0.2.7", 5000));
        } finally {
            System.clearProperty(RunSecret.DIR_PROPERTY);
        }
    }

    @Test
    void theFolderOfTheFilesCanBeMoved() throws IOException {
        RunSecret.write(dir.resolve("elsewhere/7000"), A);

        assertEquals(A, RunSecret.find(null, 7000, properties(null),
                Map.of(RunSecret.DIR_ENV, dir.resolve("elsewhere").toString())));
    }

    @Test
    void theFileIsReadableOnlyByItsOwner() throws IOException {
        Path file = dir.resolve("fresh/tokens/5000");

        RunSecret.write(file, A);

        assertEquals(A + "\n", Files.readString(file));
        if (file.getFileSystem().supportedFileAttributeViews().contains("posix")) {
            assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
            assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file.getParent())));
        }
    }

    @Test
    void aSecretThatBreaksTheRuleIsRefusedSayingWhereItCameFromWithoutRepeatingIt() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunSecret.find(null, 5000, properties(null), Map.of(RunSecret.ENV, "short secret")));

        assertEquals("the run secret from the environment variable ROBOSIM_TOKEN breaks the rule: a run secret is 16"
                + " to 128 letters, digits, '-' or '_'", e.getMessage());
    }

    @Test
    void aNamedFileThatIsMissingIsAnErrorNamingIt() {
        Path missing = dir.resolve("missing");

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> RunSecret.find(null, 5000,
                properties(null), Map.of(RunSecret.FILE_ENV, missing.toString())));

        assertTrue(e.getMessage().startsWith("cannot read the run secret from the file " + missing
                + " (named by ROBOSIM_TOKEN_FILE)"), e.getMessage());
    }

    @Test
    void secretsCompareWholeAndNeverMatchNothing() {
        assertTrue(RunSecret.matches(A, A));
        assertFalse(RunSecret.matches(A, B));
        assertFalse(RunSecret.matches(A, A.substring(1)));
        assertFalse(RunSecret.matches(A, null));
        assertFalse(RunSecret.matches(null, null));
    }
}
