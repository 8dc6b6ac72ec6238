package robosim.params;

import java.util.Locale;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * The keys of ARIA's robot parameter files that RoboSim reads past without a word: ARIA's
 * {@code ArRobotParams} defines them (IO settings, bumpers, IR, GPS, compass, the sonar boards,
 * the lasers' ports and flags, batteries, LCDs, pan/tilt units, video), so an ARIA file that has
 * them is as ARIA writes it. A key in neither this list nor RoboSim's own is unknown, and the
 * reader names it in the file's one warning.
 */
final class AriaKeys {
    private static final Set<String> KEYS = Set.of(
            // General settings and movement control
            "holonomic", "maxlatvelocity", "hasmovecommand", "requestiopackets", "requestencoderpackets",
            "switchtobaudrate", "settablevelmaxes", "settableaccsdecs", "haslatvel", "latvelmax", "lataccel",
            "latdecel",
            // Conversion factors (read by ConversionFactors, not by the record)
            "angleconvfactor", "distconvfactor", "velconvfactor", "rangeconvfactor", "vel2divisor", "gyroscaler",
            // Accessories, IR, GPS, compass
            "tablesensingir", "newtablesensingir", "frontbumpers", "numfrontbumpers", "rearbumpers",
            "numrearbumpers", "irnum", "irunit", "gpspx", "gpspy", "gpstype", "gpsport", "gpsbaud",
            "compasstype", "compassport",
            // RoboSim's sonar firing period, read by ParameterFileReader.sonarCycle, not by the record
            "sonarcycle",
            // Sonar boards
            "sonarautoconnect", "sonarboardtype", "sonarboardporttype", "sonarboardport", "sonarboardpoweroutput",
            "sonarbaud", "sonardelay", "sonargain", "sonardetectionthreshold", "sonarnoisedelta",
            // Lasers, beyond their pose and range
            "laserautoconnect", "laserpossessed", "laserpossibleconnections", "laserz", "laserignore",
            "laserflipped", "lasertype", "laserporttype", "laserport", "laserpoweroutput",
            "laserstartingbaudchoice", "laserautobaudchoice", "laserpowercontrolled", "lasercumulativebuffersize",
            "laserstartdegrees", "laserenddegrees", "laserdegreeschoice", "laserincrement",
            "laserincrementchoice", "laserunitschoice", "laserreflectorbitschoice",
            // Batteries and LCDs
            "batteryautoconnect", "batterytype", "batteryporttype", "batteryport", "batterybaud",
            "lcdautoconnect", "lcddisconnectonconnectfailure", "lcdtype", "lcdporttype", "lcdport",
            "lcdpoweroutput", "lcdbaud",
            // Pan/tilt units and video
            "ptzautoconnect", "ptztype", "ptzinverted", "ptzserialport", "ptzrobotauxserialport", "ptzaddress",
            "ptztcpport", "ptzusername", "ptzpassword", "videoautoconnect", "videotype", "videoinverted",
            "videowidth", "videoheight", "videodeviceindex", "videodevicename", "videochannel",
            "videoanalogsignalformat", "videoaddress", "videotcpport", "videousername", "videopassword");

    /** A sonar board's section: its keys, {@code SonarMaxRange} included, describe the board, not the ring. */
    private static final Pattern SONAR_BOARD = Pattern.compile("sonarboard_\\d+", Pattern.CASE_INSENSITIVE);

    private AriaKeys() {
    }

    /** @return whether ARIA defines {@code key} (any case) though RoboSim does not model it */
    static boolean isAriaOnly(String key) {
        return KEYS.contains(key.toLowerCase(Locale.ROOT));
    }

    /** @return whether {@code section} is a sonar board's ({@code SonarBoard_1}, ...) */
    static boolean isSonarBoard(String section) {
        return SONAR_BOARD.matcher(section.trim()).matches();
    }
}
