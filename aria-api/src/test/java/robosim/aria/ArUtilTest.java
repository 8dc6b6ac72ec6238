package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** ArUtil's calls as ARIA's (ariaUtil.h, ariaUtil.cpp), with its answers for null and bad input. */
class ArUtilTest {
    private static final char S = ArUtil.getSlash();

    @Test
    void bitsAreSingleBits() {
        assertEquals(1, ArUtil.BIT0);
        assertEquals(0x80, ArUtil.BIT7);
        assertEquals(0x8000, ArUtil.BIT15);
    }

    @Test
    void strcmpPutsNullFirst() {
        assertEquals(0, ArUtil.strcmp(null, null));
        assertEquals(-1, ArUtil.strcmp(null, ""));
        assertEquals(1, ArUtil.strcmp("", null));
        assertEquals(0, ArUtil.strcmp("abc", "abc"));
        assertEquals(-1, ArUtil.strcmp("abc", "abd"));
        assertEquals(1, ArUtil.strcmp("abc", "ab"));
        assertEquals(-1, ArUtil.strcmp("Z", "a"), "case counts: 'Z' is before 'a'");
    }

    @Test
    void strcasecmpLowersAsciiAsC() {
        assertEquals(0, ArUtil.strcasecmp("Robot", "rOBOT"));
        assertEquals(1, ArUtil.strcasecmp("Z", "a"));
        assertEquals(-1, ArUtil.strcasecmp("_", "A"), "'_' is before 'a'");
        assertEquals(-1, ArUtil.strcasecmp(null, "a"));
        assertEquals(1, ArUtil.strcasecmp("a", null));
        assertEquals(0, ArUtil.strcasecmp(null, null));
    }

    @Test
    void suffixNeedsTwoCharactersMoreThanTheSuffixAsInAria() {
        assertTrue(ArUtil.strSuffixCmp("ab.p", ".p"));
        assertFalse(ArUtil.strSuffixCmp("a.p", ".p"), "ARIA's rule: strlen(str) > strlen(suffix) + 1");
        assertFalse(ArUtil.strSuffixCmp("ab.P", ".p"));
        assertTrue(ArUtil.strSuffixCaseCmp("ab.P", ".p"));
        assertFalse(ArUtil.strSuffixCmp(null, ".p"));
        assertFalse(ArUtil.strSuffixCmp("abc", ""));
        assertFalse(ArUtil.strSuffixCaseCmp("abcd", null));
    }

    @Test
    void strcasequotecmpIgnoresCaseAndSurroundingQuotes() {
        assertEquals(0, ArUtil.strcasequotecmp("\"Robot\"", "robot"));
        assertEquals(0, ArUtil.strcasequotecmp("ROBOT", "\"robot\""));
        assertEquals(-1, ArUtil.strcasequotecmp("\"robot", "robot"), "a lone quote stays, and sorts before letters");
        assertEquals(-1, ArUtil.strcasequotecmp("\"a\"", "b"));
        assertEquals(0, ArUtil.strcasequotecmp("\"", "\""));
    }

    @Test
    void stripQuotesTakesOnlyASurroundingPair() {
        assertEquals("a b", ArUtil.stripQuotes("\"a b\""));
        assertEquals("\"a", ArUtil.stripQuotes("\"a"));
        assertEquals("", ArUtil.stripQuotes("\"\""));
        assertEquals("\"", ArUtil.stripQuotes("\""));
        assertEquals("a\"b\"c", ArUtil.stripQuotes("a\"b\"c"));
        assertNull(ArUtil.stripQuotes(null));
    }

    @Test
    void escapeSpacesAndLower() {
        assertEquals("my\\ robot\\ 1", ArUtil.escapeSpaces("my robot 1"));
        assertEquals("abc-xyz éÉ", ArUtil.lower("ABC-xyz éÉ"), "only A to Z change, as C's tolower");
    }

    @Test
    void fixBadCharactersFollowsAriasOrder() {
        assertEquals("[a]-b c-d", ArUtil.fixBadCharacters("(a)!b c/d", false));
        assertEquals("[a]-b-c-d", ArUtil.fixBadCharacters("<a>#b c\td", true));
        assertEquals("a b", ArUtil.fixBadCharacters("a\tb", false, true), "other white space becomes a space");
        assertEquals("a\tb", ArUtil.fixBadCharacters("a\tb", false, false));
        assertEquals("x.y_z+[]", ArUtil.fixBadCharacters("x.y_z+{}", false));
        assertNull(ArUtil.fixBadCharacters(null, true));
    }

    @Test
    void onlyAlphaNumericAndOnlyNumericAllowPlusAndMinus() {
        assertTrue(ArUtil.isOnlyAlphaNumeric("abc123+-"));
        assertFalse(ArUtil.isOnlyAlphaNumeric("abc 123"));
        assertFalse(ArUtil.isOnlyAlphaNumeric("é"));
        assertTrue(ArUtil.isOnlyAlphaNumeric(""));
        assertTrue(ArUtil.isOnlyAlphaNumeric(null));
        assertTrue(ArUtil.isOnlyNumeric("-12+3"));
        assertFalse(ArUtil.isOnlyNumeric("1.5"));
        assertFalse(ArUtil.isOnlyNumeric("12a"));
        assertTrue(ArUtil.isOnlyNumeric(null));
    }

    @Test
    void emptyStringsAndLists() {
        assertTrue(ArUtil.isStrEmpty(null));
        assertTrue(ArUtil.isStrEmpty(""));
        assertFalse(ArUtil.isStrEmpty(" "));
        List<String> names = List.of("Sonar", "Laser");
        assertTrue(ArUtil.isStrInList("Laser", names));
        assertFalse(ArUtil.isStrInList("laser", names));
        assertTrue(ArUtil.isStrInList("laser", names, true));
        assertFalse(ArUtil.isStrInList(null, names, true));
    }

    @Test
    void convertBoolIsCsTruth() {
        assertEquals("true", ArUtil.convertBool(5));
        assertEquals("true", ArUtil.convertBool(-1));
        assertEquals("false", ArUtil.convertBool(0));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {"12.5mm|12.5", "  -3|-3", "1e3|1000", "1e|1", ".5|0.5", "5.|5", "abc|0", "|0",
        "0x10|16", "0x1.8p1|3", "+.25e+2x|25", "-|0", "1e-2|0.01"})
    void atofReadsTheNumberAtTheStartAsC(String text, double value) {
        assertEquals(value, ArUtil.atof(text == null ? "" : text), 1e-12);
    }

    @Test
    void atofOfInfinitiesNaNAndNull() {
        assertEquals(Double.POSITIVE_INFINITY, ArUtil.atof("inf"));
        assertEquals(Double.NEGATIVE_INFINITY, ArUtil.atof("-INF"));
        assertEquals(Double.POSITIVE_INFINITY, ArUtil.atof("Infinity"));
        assertTrue(Double.isNaN(ArUtil.atof("nan")));
        assertEquals(0, ArUtil.atof(null));
    }

    @Test
    void readDoubleValueNeedsTheWholeString() {
        boolean[] ok = {false};
        assertEquals(2.5, ArUtil.readDoubleValue(" 2.5", ok));
        assertTrue(ok[0]);
        assertEquals(0, ArUtil.readDoubleValue("2.5 ", ok));
        assertFalse(ok[0]);
        assertEquals(0, ArUtil.readDoubleValue("", ok));
        assertFalse(ok[0]);
        ok[0] = true;
        assertEquals(0, ArUtil.readDoubleValue(null, ok));
        assertFalse(ok[0]);
    }

    @Test
    void atoiNeedsTheWholeStringAndReadsHexAfter0x() {
        boolean[] ok = {false};
        assertEquals(42, ArUtil.atoi("42", ok, false));
        assertTrue(ok[0]);
        assertEquals(-7, ArUtil.atoi(" -7", ok, false));
        assertTrue(ok[0]);
        assertEquals(0, ArUtil.atoi("42x", ok, false));
        assertFalse(ok[0]);
        assertEquals(0, ArUtil.atoi("", ok, false));
        assertFalse(ok[0]);
        assertEquals(255, ArUtil.atoi("0xff", ok, false));
        assertTrue(ok[0]);
        assertEquals(255, ArUtil.atoi("ff", ok, true));
        assertTrue(ok[0]);
        assertEquals(0, ArUtil.atoi("ff", ok, false));
        assertFalse(ok[0]);
        assertEquals(0, ArUtil.atoi("0x", ok, false), "two characters: no hex prefix, and 'x' is no digit");
        assertFalse(ok[0]);
        assertEquals(0, ArUtil.atoi("1.5", ok, false));
        assertFalse(ok[0]);
    }

    @Test
    void atoiRefusesValuesOutsideAnInt() {
        boolean[] ok = {true};
        assertEquals(Integer.MAX_VALUE, ArUtil.atoi("2147483647", ok, false));
        assertTrue(ok[0]);
        assertEquals(0, ArUtil.atoi("2147483648", ok, false));
        assertFalse(ok[0]);
        assertEquals(Integer.MIN_VALUE, ArUtil.atoi("-2147483648", ok, false));
        assertTrue(ok[0]);
        assertEquals(0, ArUtil.atoi("-3000000000", ok, false));
        assertFalse(ok[0]);
        assertEquals(0, ArUtil.atoi("99999999999999999999999", ok, false));
        assertFalse(ok[0]);
        assertEquals(0, ArUtil.atoi(null, ok, false));
        assertFalse(ok[0]);
        assertEquals(12, ArUtil.atoi("12"));
    }

    @Test
    void findMinAndFindMax() {
        assertEquals(2, ArUtil.findMin(2, 3));
        assertEquals(3, ArUtil.findMax(2, 3));
        assertEquals(-1.5, ArUtil.findMin(-1.5, 0.5));
        assertEquals(0.5, ArUtil.findMax(-1.5, 0.5));
        assertTrue(Double.isNaN(ArUtil.findMin(1.0, Double.NaN)), "the second when the comparison fails");
        assertEquals(1.0, ArUtil.findMin(Double.NaN, 1.0));
    }

    @Test
    void pathHelpers() {
        assertEquals("a" + S, ArUtil.appendSlash("a"));
        assertEquals("a/", ArUtil.appendSlash("a/"));
        assertEquals("a\\", ArUtil.appendSlash("a\\"));
        assertEquals(String.valueOf(S), ArUtil.appendSlash(""));
        assertEquals("a/b/c", ArUtil.fixSlashesForward("a\\b/c"));
        assertEquals("a\\b\\c", ArUtil.fixSlashesBackward("a\\b/c"));
        String mixed = "x/y\\z";
        assertEquals(("x" + S + "y" + S + "z"), ArUtil.fixSlashes(mixed));
        assertEquals("base" + S + "inside" + S, ArUtil.addDirectories("base", "inside"));
        assertEquals("base" + S + "inside" + S, ArUtil.addDirectories("base/", "inside\\"));
        assertEquals(S + "inside" + S, ArUtil.addDirectories("", "inside"));
    }

    @Test
    void directoryAndFileNames() {
        assertEquals("params" + S + "p3dx", ArUtil.getDirectory("params/p3dx/p3dx.p"));
        assertEquals("", ArUtil.getDirectory("p3dx.p"));
        assertEquals("", ArUtil.getDirectory("/p3dx.p"));
        assertNull(ArUtil.getDirectory(""));
        assertNull(ArUtil.getDirectory(null));
        assertEquals("p3dx.p", ArUtil.getFileName("params/p3dx.p"));
        assertEquals("p3dx.p", ArUtil.getFileName("p3dx.p"));
        assertEquals("", ArUtil.getFileName("params/"));
        assertNull(ArUtil.getFileName(""));
    }

    @Test
    void insertSuffixBeforeTheLastDot() {
        assertEquals("map_old.map", ArUtil.insertSuffixBeforeExtension("map.map", "_old"));
        assertEquals("log_1", ArUtil.insertSuffixBeforeExtension("log", "_1"));
        assertEquals("a.b_1.c", ArUtil.insertSuffixBeforeExtension("a.b.c", "_1"));
        assertEquals("dir_1.d/file", ArUtil.insertSuffixBeforeExtension("dir.d/file", "_1"), "ARIA looks at the whole name");
    }

    @Test
    void filesFoundSizedAndRead(@TempDir Path dir) throws IOException {
        Path f = dir.resolve("robot.txt");
        Files.writeString(f, "first line\r\nsecond\n");
        assertTrue(ArUtil.findFile(f.toString()));
        assertEquals(19, ArUtil.sizeFile(f.toString()));
        assertEquals("first line", ArUtil.getStringFromFile(f.toString()));
        assertFalse(ArUtil.findFile(dir.resolve("none").toString()));
        assertFalse(ArUtil.findFile(dir.toString()), "a directory is no file");
        assertEquals(-1, ArUtil.sizeFile(dir.resolve("none").toString()));
        assertNull(ArUtil.getStringFromFile(dir.resolve("none").toString()));
        Path empty = dir.resolve("empty");
        Files.writeString(empty, "");
        assertNull(ArUtil.getStringFromFile(empty.toString()));
        assertFalse(ArUtil.findFile(null));
    }

    @Test
    void unitsAndNormalFloats() {
        assertEquals(1500, ArUtil.secToMSec(1.5));
        assertEquals(0.25, ArUtil.mSecToSec(250));
        assertEquals(3.2808399, ArUtil.metersToFeet(1), 1e-12);
        assertEquals(1, ArUtil.feetToMeters(3.2808399), 1e-12);
        assertTrue(ArUtil.floatIsNormal(1.0));
        assertFalse(ArUtil.floatIsNormal(0.0), "isnormal is false for 0");
        assertFalse(ArUtil.floatIsNormal(Double.MIN_VALUE), "and for subnormal numbers");
        assertFalse(ArUtil.floatIsNormal(Double.NaN));
        assertFalse(ArUtil.floatIsNormal(Double.POSITIVE_INFINITY));
    }

    @Test
    void getTimeIsSimulatedTimeLikeArTime() {
        assertEquals(new ArTime().getTimeMs(), ArUtil.getTime());
    }
}
