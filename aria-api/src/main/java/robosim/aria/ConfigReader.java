package robosim.aria;

import java.io.BufferedReader;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Reads a configuration file's lines into an {@link ArConfig}, as ARIA's {@code ArFileParser}
 * hands them to {@code ArConfig}'s handlers: {@code ConfigVersion}, {@code Section}, a parameter's
 * name, or anything else (an unknown parameter, kept). Also reads parameters from an argument
 * parser ({@code ArConfig::parseArgumentParser}).
 */
final class ConfigReader {
    private final ArConfig config;

    ConfigReader(ArConfig config) {
        this.config = config;
    }

    /** ARIA's {@code ArFileParser::parseFile}, with no error buffer (as AriaCoda's {@code ArConfig} calls it). */
    boolean parseFile(String realFileName, boolean continueOnErrors, boolean noFileNotFoundMessage) {
        BufferedReader in;
        try {
            in = new BufferedReader(new InputStreamReader(new FileInputStream(realFileName), StandardCharsets.UTF_8));
        } catch (IOException e) {
            if (!noFileNotFoundMessage) {
                ArLog.log(ArLog.Terse, "ArFileParser::parseFile: Could not open file %s to parse file.", realFileName);
            }
            return false;
        }
        boolean ret = true;
        int lineNumber = 0;
        try (in) {
            String line;
            while ((line = in.readLine()) != null) {
                lineNumber++;
                if (!parseLine(line)) {
                    ArLog.log(ArLog.Terse, "## Last error on line %d of file '%s'", lineNumber, realFileName);
                    ret = false;
                    if (!continueOnErrors) {
                        break;
                    }
                }
            }
        } catch (IOException e) {
            ArLog.log(ArLog.Terse, "ArFileParser::parseFile: Could not read file %s after line %d: %s", realFileName,
                    lineNumber, e.getMessage());
            return false;
        }
        return ret;
    }

    private boolean parseLine(String raw) {
        ConfigText.Line line = ConfigText.split(raw);
        if (line == null) {
            return true;
        }
        String keyword = line.keyword().toLowerCase(Locale.ROOT);
        if (keyword.equals("configversion")) {
            return parseVersion(line.words());
        }
        if (keyword.equals("section")) {
            return parseSection(String.join(" ", line.words()));
        }
        if (config.paramNames.contains(keyword)) {
            return parseArgument(keyword, line.words(), null, 0);
        }
        return parseUnknown(line.allWords());
    }

    /** ARIA's {@code ArConfig::parseVersion}. */
    private boolean parseVersion(List<String> words) {
        if (words.isEmpty()) {
            return false;
        }
        config.configVersion = words.get(0);
        ArLog.log(ArLog.Normal, "%sConfig version: %s", config.logPrefix, config.configVersion);
        return true;
    }

    /** ARIA's {@code ArConfig::parseSection}: later lines are that section's. */
    private boolean parseSection(String name) {
        if (config.findSection(name) != null) {
            ArLog.log(ArLog.Verbose, "%sConfig switching to section '%s'", config.logPrefix, name);
            switchTo(name, false, false);
            config.usingSections = true;
            return true;
        }
        if (config.failOnBadSection) {
            switchTo("", true, false);
            ArLog.log(ArLog.Terse, "%sCould not find section '%s', failing", config.logPrefix, name);
            return false;
        }
        if (config.saveUnknown) {
            ArLog.log(ArLog.Verbose, "%smaking new section '%s' to save unknown", config.logPrefix, name);
            switchTo(name, false, false);
            config.getSections().add(new ArConfigSection(name, null));
        } else {
            switchTo("", false, true);
            ArLog.log(ArLog.Normal, "%sIgnoring unknown section '%s'", config.logPrefix, name);
        }
        return true;
    }

    private void switchTo(String name, boolean broken, boolean ignored) {
        config.section = name;
        config.sectionBroken = broken;
        config.sectionIgnored = ignored;
    }

    /** ARIA's {@code ArConfig::parseArgument}: sets the current section's parameters of that name. */
    private boolean parseArgument(String name, List<String> words, StringBuilder errorBuffer, int errorBufferLen) {
        if (config.sectionBroken) {
            ArLog.log(ArLog.Verbose, "%sSkipping parameter %s because section broken", config.logPrefix, name);
            if (config.failOnBadSection) {
                ConfigText.putError(errorBuffer, errorBufferLen, "Failed because broken config section");
                return false;
            }
            return true;
        }
        if (config.sectionIgnored) {
            return true;
        }
        if (config.duplicateParams && config.usingSections && config.section.isEmpty()) {
            ConfigText.putError(errorBuffer, errorBufferLen, name + " not in section, client needs an upgrade");
            ArLog.log(ArLog.Normal, "%s%s not in a section, client needs an upgrade", config.logPrefix, name);
            return false;
        }
        if (errorBuffer != null) {
            errorBuffer.setLength(0);
        }
        boolean found = false;
        boolean ret = true;
        ArConfigSection s = config.findSection(config.section);
        for (ArConfigArg p : s == null ? List.<ArConfigArg>of() : List.copyOf(s.getParams())) {
            if (!p.getName().equalsIgnoreCase(name)) {
                continue;
            }
            found = true;
            if (!ConfigText.parseArgument(p, words, errorBuffer, errorBufferLen, config.logPrefix)) {
                ArLog.log(ArLog.Normal, "ArConfig::parseArgument() error parsing %s", String.join(" ", words));
                ret = false;
            }
        }
        if (!found) {
            List<String> unknown = new ArrayList<>();
            unknown.add(name);
            unknown.addAll(words);
            return parseUnknown(unknown);
        }
        return ret;
    }

    /** ARIA's {@code ArConfig::parseUnknown}: keeps the line (name and text) in the current section. */
    private boolean parseUnknown(List<String> words) {
        if (words.isEmpty()) {
            return true;
        }
        String name = words.get(0);
        String text = String.join(" ", words.subList(1, words.size()));
        if (!config.saveUnknown) {
            ArLog.log(ArLog.Verbose, "%sUnknown '%s' in section '%s', ignoring it", config.logPrefix,
                    String.join(" ", words), config.section);
            return true;
        }
        ArLog.log(ArLog.Verbose, words.size() < 2 ? "%sNo arg for param '%s%s' in section '%s', saving it anyways"
                : "%sUnknown '%s %s' in section '%s', saving it", config.logPrefix, name, text, config.section);
        config.addParam(new ArConfigArg(name, text), config.section);
        return true;
    }

    /** ARIA's {@code ArConfig::parseArgumentParser}. */
    boolean parseArgumentParser(ArArgumentParser parser, boolean continueOnError, StringBuilder errorBuffer,
            int errorBufferLen) {
        for (int i = 0; i < parser.getArgc(); i++) {
            String arg = parser.getArg(i);
            String undashed = arg.startsWith("-") ? arg.substring(1) : "";
            for (ArConfigSection s : config.getSections()) {
                for (ArConfigArg p : s.getParams()) {
                    if (p.getName().isEmpty() || !(p.getName().equalsIgnoreCase(arg)
                            || p.getName().equalsIgnoreCase(undashed))) {
                        continue;
                    }
                    List<String> words = i + 1 < parser.getArgc() ? ConfigText.words(parser.getArg(i + 1)) : List.of();
                    if (i + 1 < parser.getArgc()) {
                        parser.removeArg(i + 1);
                    }
                    parser.removeArg(i);
                    boolean ret = parseIn(s.getName(), p.getName(), words, errorBuffer, errorBufferLen);
                    // as ARIA's: a refused value ends the reading, continueOnError or not
                    return ret && parseArgumentParser(parser, continueOnError, errorBuffer, errorBufferLen);
                }
            }
        }
        return true;
    }

    /** Parses one parameter as if in its section, the reading state kept. */
    private boolean parseIn(String sectionName, String name, List<String> words, StringBuilder errorBuffer,
            int errorBufferLen) {
        String oldSection = config.section;
        boolean oldBroken = config.sectionBroken;
        boolean oldIgnored = config.sectionIgnored;
        boolean oldUsing = config.usingSections;
        boolean oldDuplicates = config.duplicateParams;
        switchTo(sectionName, false, false);
        config.usingSections = true;
        config.duplicateParams = false;
        try {
            return parseArgument(name, words, errorBuffer, errorBufferLen);
        } finally {
            switchTo(oldSection, oldBroken, oldIgnored);
            config.usingSections = oldUsing;
            config.duplicateParams = oldDuplicates;
        }
    }
}
