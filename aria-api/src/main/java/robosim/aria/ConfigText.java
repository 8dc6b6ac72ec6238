package robosim.aria;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * The text of ARIA's configuration files: how a line splits into a keyword and its words (ARIA's
 * {@code ArFileParser::parseLine} and {@code ArArgumentBuilder}), how a parameter reads its words
 * ({@code ArConfigArg::parseArgument}) and how a config is written ({@code ArConfig::writeFile},
 * {@code ArConfigArg::writeArguments} and {@code writeMultiLineComment}).
 */
final class ConfigText {
    /** The column a parameter's comment starts at, and the width comments wrap at (ARIA's 25 and 80). */
    static final int COMMENT_COLUMN = 25;
    static final int LINE_WRAP = 80;

    /** A line's keyword (as written, quotes taken off), the words after it, and all of its words. */
    record Line(String keyword, List<String> words, List<String> allWords) {
    }

    private ConfigText() {
    }

    /** C's {@code isspace}. */
    static boolean isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\u000b' || c == '\f' || c == '\r';
    }

    /** @return the words of a text, split at white space (ARIA's {@code ArArgumentBuilder::addPlain}) */
    static List<String> words(String text) {
        List<String> words = new ArrayList<>();
        int i = 0;
        while (i < text.length()) {
            while (i < text.length() && isSpace(text.charAt(i))) {
                i++;
            }
            int start = i;
            while (i < text.length() && !isSpace(text.charAt(i))) {
                i++;
            }
            if (i > start) {
                words.add(text.substring(start, i));
            }
        }
        return words;
    }

    /**
     * Splits a line as ARIA's {@code ArFileParser::parseLine}: the comment cut at ';' or '#', the
     * keyword the first word (or the text between quotes), the value what follows.
     *
     * @return the line's parts, or null for a blank or comment line
     */
    static Line split(String raw) {
        String line = raw;
        for (String delimiter : new String[] {";", "#"}) {
            int at = line.indexOf(delimiter);
            if (at >= 0) {
                line = line.substring(0, at);
            }
        }
        line = line.replace("\r", "").replace("\n", "");
        int start = 0;
        while (start < line.length() && isSpace(line.charAt(start))) {
            start++;
        }
        if (start == line.length()) {
            return null;
        }
        int i = start;
        String keyword;
        if (line.charAt(i) == '"') {
            // ARIA's text starts after the quote: an unknown quoted name keeps only its closing quote
            start++;
            int close = line.indexOf('"', start);
            keyword = close < 0 ? line.substring(start) : line.substring(start, close);
            i = close < 0 ? line.length() : close + 1;
        } else {
            while (i < line.length() && !isSpace(line.charAt(i))) {
                i++;
            }
            keyword = line.substring(start, i);
        }
        return new Line(keyword, words(line.substring(i)), words(line.substring(start)));
    }

    /** Puts a reason in an error buffer as C's {@code snprintf(errorBuffer, errorBufferLen, ...)} does. */
    static void putError(StringBuilder errorBuffer, int errorBufferLen, String reason) {
        if (errorBuffer == null) {
            return;
        }
        errorBuffer.setLength(0);
        errorBuffer.append(errorBufferLen > 0 && reason.length() > errorBufferLen - 1
                ? reason.substring(0, errorBufferLen - 1) : reason);
    }

    /**
     * Sets a parameter from a line's words, as ARIA's {@code ArConfigArg::parseArgument}.
     *
     * @return false if the value was refused (logged, and the reason put in the error buffer)
     */
    static boolean parseArgument(ArConfigArg arg, List<String> words, StringBuilder errorBuffer, int errorBufferLen,
            String logPrefix) {
        String first = words.isEmpty() ? null : words.get(0);
        String name = arg.getName();
        ArConfigArg.Type type = arg.getType();
        if (first == null && type != ArConfigArg.Type.STRING) {
            ArLog.log(ArLog.Verbose, "%sparameter '%s' has no argument.", logPrefix, name);
            return true;
        }
        switch (type) {
            case INT -> {
                Integer v = CFormats.parseInt(first);
                if (v == null) {
                    return refuse(errorBuffer, errorBufferLen,
                            name + " is an integer parameter but was given non-integer argument of '" + first + "'");
                }
                return arg.setInt(v, errorBuffer, errorBufferLen, false);
            }
            case DOUBLE -> {
                Double v = CFormats.parseDouble(first);
                if (v == null) {
                    ArLog.log(ArLog.Terse, "%sparameter '%s' is a double parameter but was given non-double argument"
                            + " of '%s'", logPrefix, name, first);
                    return refuse(errorBuffer, errorBufferLen,
                            name + " is a double parameter but was given non-double argument of '" + first + "'");
                }
                return arg.setDouble(v, errorBuffer, errorBufferLen, false);
            }
            case BOOL -> {
                Boolean v = CFormats.parseBool(first);
                if (v == null) {
                    ArLog.log(ArLog.Terse, "%sparameter '%s' is a bool parameter but was given non-bool argument of '%s'",
                            logPrefix, name, first);
                    return refuse(errorBuffer, errorBufferLen,
                            name + " is a bool parameter but was given non-bool argument of '" + first + "'");
                }
                return arg.setBool(v);
            }
            case STRING -> {
                String full = String.join(" ", words);
                if (arg.setString(full, errorBuffer, errorBufferLen, false)) {
                    return true;
                }
                if (errorBuffer != null && errorBuffer.length() == 0) {
                    putError(errorBuffer, errorBufferLen, name + " could not be set to '" + full + "'.");
                }
                return false;
            }
            case DESCRIPTION_HOLDER, SEPARATOR, STRING_HOLDER -> {
                return true;
            }
            default -> {
                ArLog.log(ArLog.Verbose, "%sWarning: Don't know the argument type for '%s' in section, got string '%s'",
                        logPrefix, name, String.join(" ", words));
                return true;
            }
        }
    }

    private static boolean refuse(StringBuilder errorBuffer, int errorBufferLen, String reason) {
        putError(errorBuffer, errorBufferLen, reason);
        return false;
    }

    /**
     * Writes a parameter as ARIA's {@code ArConfigArg::writeArguments}: {@code Name value}, then
     * its bounds and description as a comment from column 25, wrapped at 80.
     */
    static void writeArguments(ArConfigArg arg, StringBuilder out) {
        String name = arg.getName();
        if (arg.getType() != ArConfigArg.Type.STRING_HOLDER && (name.contains(" ") || name.contains("\t"))) {
            name = "\"" + name + "\"";
        }
        String line = switch (arg.getType()) {
            case INT -> name + " " + arg.getInt();
            case DOUBLE -> name + " " + (arg.getDoublePrecision() >= 0
                    ? CFormats.fixed(arg.getDouble(), arg.getDoublePrecision()) : CFormats.g(arg.getDouble()));
            case BOOL -> name + " " + (arg.getBool() ? "true" : "false");
            case STRING, STRING_HOLDER -> name + " " + arg.getString();
            case DESCRIPTION_HOLDER -> "";
            default -> {
                ArLog.log(ArLog.Terse, "ArConfig:  in writeArguments(): unhandled argument type %s for config arg %s",
                        ArConfigArg.toString(arg.getType()), arg.getName());
                yield "";
            }
        };
        if (arg.getType() == ArConfigArg.Type.STRING_HOLDER) {
            out.append(line).append('\n');
            return;
        }
        out.append(line);
        String comment = arg.getBoundsDescr();
        if (!comment.isEmpty()) {
            comment += ", ";
        }
        comment += arg.getDescription();
        if (comment.isEmpty()) {
            // AriaCoda writes the line a second time here, which its parser then misreads: once is right
            out.append('\n');
        } else {
            writeMultiLineComment(comment, out, "; ", LINE_WRAP, line.length(), line.isEmpty() ? 0 : COMMENT_COLUMN);
        }
    }

    /**
     * ARIA's {@code ArConfigArg::writeMultiLineComment}: the comment's words after {@code
     * startComment}, a new line (indented, with {@code startComment} again) before a word that
     * would pass {@code linewrap}.
     *
     * @param alreadyWritten how much of the first line is written
     * @param indent         the column comments start at
     */
    static void writeMultiLineComment(String comment, StringBuilder out, String startComment, int linewrap,
            int alreadyWritten, int indent) {
        StringBuilder line = new StringBuilder();
        if (alreadyWritten >= indent && alreadyWritten != 0) {
            line.append(' ');
        } else if (indent < linewrap) {
            line.append(" ".repeat(indent - alreadyWritten));
        }
        line.append(startComment);
        int written = alreadyWritten;
        List<String> words = words(comment);
        for (int i = 0; i < words.size(); i++) {
            String word = words.get(i);
            if (written + line.length() + word.length() + 1 > linewrap) {
                written = 0;
                out.append(line).append('\n');
                line.setLength(0);
                line.append(" ".repeat(indent)).append(startComment).append(word);
            } else {
                if (i != 0) {
                    line.append(' ');
                }
                line.append(word);
            }
        }
        out.append(line).append('\n');
    }

    /**
     * The text of ARIA's {@code ArConfig::writeFile}: {@code ConfigVersion 2.0}, the section of no
     * name first, then the others, a blank line between sections.
     */
    static String write(List<ArConfigSection> sections, boolean noBlanksBetweenParams) {
        StringBuilder out = new StringBuilder("ConfigVersion 2.0\n");
        boolean first = true;
        for (ArConfigSection s : sections) {
            if (s.getName().isEmpty()) {
                first = false;
                writeSection(s, out, noBlanksBetweenParams);
                break;
            }
        }
        for (ArConfigSection s : sections) {
            if (s.getName().isEmpty()) {
                continue;
            }
            if (!first) {
                out.append('\n');
            }
            first = false;
            writeSection(s, out, noBlanksBetweenParams);
        }
        return out.toString();
    }

    /** ARIA's {@code ArConfig::writeSection}: a name written once per section, separators left out. */
    private static void writeSection(ArConfigSection s, StringBuilder out, boolean noBlanksBetweenParams) {
        Set<String> written = new HashSet<>();
        if (!s.getName().isEmpty()) {
            out.append("Section ").append(s.getName()).append('\n');
        }
        if (!s.getComment().isEmpty()) {
            writeMultiLineComment(s.getComment(), out, "; ", LINE_WRAP, 0, 0);
        }
        out.append(";SectionFlags for ").append(s.getName()).append(": ").append(s.getFlags()).append('\n');
        for (ArConfigArg p : s.getParams()) {
            if (p.getType() == ArConfigArg.Type.SEPARATOR) {
                continue;
            }
            if (p.getType() != ArConfigArg.Type.DESCRIPTION_HOLDER && !written.add(p.getName())) {
                continue;
            }
            writeArguments(p, out);
            if (!noBlanksBetweenParams) {
                out.append('\n');
            }
        }
    }
}
