package robosim.aria;

import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

/**
 * ARIA's {@code ArConfig}: a program's parameters, in named sections, read from and written to a
 * configuration file, with callbacks run when a file has been read. The program's own is {@link
 * Aria#getConfig()}; a port reads as the C++:
 * <pre>{@code
 * ArConfig config = Aria.getConfig();
 * config.addParam(ArConfigArg.ofInt("Speed", () -> mySpeed, v -> mySpeed = v, "Speed to go.", 0, 1000),
 *         "Motion", ArPriority.NORMAL);
 * config.addProcessFileCB(myProcessConfigCB, 0);
 * StringBuilder error = new StringBuilder();
 * if (!config.parseFile(fileName, true, false, error, 512)) { ... }
 * config.writeFile(fileName);
 * }</pre>
 *
 * <p>The file is ARIA's: {@code ConfigVersion 2.0}, then {@code Section NAME} lines, each followed
 * by {@code Name value ; comment} lines; ';' and '#' start a comment. Names and sections match in
 * any case. A parameter nobody added is kept (in its section) and written back; a value out of a
 * parameter's bounds is refused with ARIA's log lines. As AriaCoda's {@code parseFile}, the error
 * buffer gets only the process-file callbacks' reasons: a refused value is logged with its line.
 * Where C++ passes a {@code char *} buffer and its size, Java passes a {@link StringBuilder} and the
 * size (0: any). Follows ARIA's {@code ArConfig.h} and {@code ArConfig.cpp}; lists, translations,
 * resource files and restart levels are left out.
 */
public class ArConfig {

    /** Sections about I/O, ARCL, display and network communication (ARIA's category names). */
    public static final String CATEGORY_ROBOT_INTERFACE = "Robot Interface";
    /** Sections about the robot's behaviour: docking, driving, navigation. */
    public static final String CATEGORY_ROBOT_OPERATION = "Robot Operation";
    /** Sections about the robot's hardware, sensors and accessories. */
    public static final String CATEGORY_ROBOT_PHYSICAL = "Robot Physical";
    /** Sections about the fleet. */
    public static final String CATEGORY_FLEET = "Enterprise";
    /** Sections about security. */
    public static final String CATEGORY_SECURITY = "Security";
    /** Sections about debugging: logging, replay. */
    public static final String CATEGORY_DEBUG = "Debug";

    /** A process-file callback, called with the error buffer. */
    private record ProcessFileCB(Object functor, int priority, Predicate<StringBuilder> call) {
    }

    private final List<ArConfigSection> sections = new ArrayList<>();
    private final List<ProcessFileCB> processFileCBs = new ArrayList<>();
    private final Map<String, List<String>> categoryToSections = new TreeMap<>();
    private final boolean ignoreBounds;
    private boolean noBlanksBetweenParams;
    private String baseDirectory = "";
    private String fileName = "";
    private ArArgumentParser argumentParser;
    private ArLog.LogLevel processFileCallbacksLogLevel = ArLog.Verbose;

    // what reading a file needs (ConfigReader): ARIA keeps it in the config between lines and calls
    final String logPrefix = "ArConfig: ";
    /** The lower-case names of every parameter added: ARIA's file parser's keywords. */
    final Set<String> paramNames = new HashSet<>();
    final boolean failOnBadSection;
    boolean saveUnknown;
    String configVersion = "";
    String section = "";
    boolean sectionBroken;
    boolean sectionIgnored;
    boolean usingSections;
    boolean duplicateParams;

    /** A config with no base directory, blank lines between parameters, bounds checked, unknowns kept. */
    public ArConfig() {
        this(null, false, false, false, true);
    }

    /**
     * ARIA's {@code ArConfig} constructor.
     *
     * @param baseDirectory         where relative file names are, or null
     * @param noBlanksBetweenParams whether the written file has no blank line after each parameter
     * @param ignoreBounds          whether parameters take values out of their bounds (debugging)
     * @param failOnBadSection      whether a {@code Section} line naming no known section is an error
     * @param saveUnknown           whether parameters and sections nobody added are kept and written back
     */
    public ArConfig(String baseDirectory, boolean noBlanksBetweenParams, boolean ignoreBounds,
            boolean failOnBadSection, boolean saveUnknown) {
        setBaseDirectory(baseDirectory);
        this.noBlanksBetweenParams = noBlanksBetweenParams;
        this.ignoreBounds = ignoreBounds;
        this.failOnBadSection = failOnBadSection;
        this.saveUnknown = saveUnknown;
    }

    /**
     * Adds a parameter to a section (made if new), as ARIA's {@code ArConfig::addParam}: the
     * config keeps a copy (sharing the value) with the priority and display hint, white space in
     * its name made '_'. A name already in another section is noted (then a parameter outside any
     * section is refused when read, as ARIA's).
     *
     * @param arg         the parameter
     * @param sectionName its section ("" for none)
     * @param priority    how important it is
     * @param displayHint a hint for an editor's control, or null
     * @return true
     */
    public boolean addParam(ArConfigArg arg, String sectionName, ArPriority priority, String displayHint) {
        ArConfigSection s = findSection(sectionName);
        if (s == null) {
            ArLog.log(ArLog.Verbose, "ArConfigArg %s: Making new section '%s' (for param)", logPrefix, sectionName);
            s = new ArConfigSection(sectionName, null);
            sections.add(s);
        }
        List<ArConfigArg> params = s.getParams();
        if (arg.getType() == ArConfigArg.Type.SEPARATOR && !params.isEmpty()
                && params.get(params.size() - 1).getType() == ArConfigArg.Type.SEPARATOR) {
            return true;
        }
        for (ArConfigSection other : sections) {
            ArConfigArg existing = arg.getName().isEmpty() ? null : other.findParam(arg.getName());
            if (existing == null) {
                continue;
            }
            if (!other.getName().equalsIgnoreCase(s.getName())) {
                ArLog.log(ArLog.Verbose, "%sParameter %s (type %s) name duplicated in section %s and %s", logPrefix,
                        arg.getName(), ArConfigArg.toString(arg.getType()), other.getName(), s.getName());
                duplicateParams = true;
            } else {
                ArLog.log(existing.isPlaceholder() ? ArLog.Verbose : ArLog.Normal,
                        "%sParameter %s (type %s) already exists in section %s (placeholder = %d)", logPrefix,
                        arg.getName(), ArConfigArg.toString(arg.getType()), s.getName(), existing.isPlaceholder() ? 1 : 0);
            }
        }
        paramNames.add(arg.getName().toLowerCase(Locale.ROOT));
        s.remStringHolder(arg.getName());
        ArConfigArg kept = arg.copy();
        kept.setConfigPriority(priority);
        kept.setDisplayHint(displayHint);
        kept.setIgnoreBounds(ignoreBounds);
        kept.replaceSpacesInName();
        params.add(kept);
        return true;
    }

    /** @param arg the parameter @param sectionName its section @param priority how important it is @return true */
    public boolean addParam(ArConfigArg arg, String sectionName, ArPriority priority) {
        return addParam(arg, sectionName, priority, null);
    }

    /** @param arg the parameter @param sectionName its section, at {@link ArPriority#NORMAL} @return true */
    public boolean addParam(ArConfigArg arg, String sectionName) {
        return addParam(arg, sectionName, ArPriority.NORMAL, null);
    }

    /** @param arg a parameter of no section, at {@link ArPriority#NORMAL} @return true */
    public boolean addParam(ArConfigArg arg) {
        return addParam(arg, "", ArPriority.NORMAL, null);
    }

    /** @param arg a parameter whose priority and hint are set @param sectionName its section @return true */
    public boolean addParamAsIs(ArConfigArg arg, String sectionName) {
        return addParam(arg, sectionName, arg.getConfigPriority(), arg.getDisplayHint());
    }

    /** @param comment a comment line @param sectionName its section @param priority its priority @return true */
    public boolean addComment(String comment, String sectionName, ArPriority priority) {
        return addParam(new ArConfigArg(comment), sectionName, priority);
    }

    /** @param comment a comment line of a section @param sectionName the section @return true */
    public boolean addComment(String comment, String sectionName) {
        return addComment(comment, sectionName, ArPriority.NORMAL);
    }

    /**
     * Adds a section to a category with its description, or puts a section of no category in one:
     * ARIA's {@code ArConfig::addSection}.
     *
     * @param categoryName       one of the {@code CATEGORY_} names ("" for none)
     * @param sectionName        the section (made if new)
     * @param sectionDescription its comment
     * @return false (logged) if the category is null, the name empty, or the section already in a category
     */
    public boolean addSection(String categoryName, String sectionName, String sectionDescription) {
        if (categoryName == null || sectionName == null || sectionName.isEmpty()) {
            ArLog.log(ArLog.Normal, "%sFailed to add section '%s' to category '%s'", logPrefix, sectionName,
                    categoryName);
            return false;
        }
        ArConfigSection s = findSection(sectionName);
        if (s != null && !s.getCategoryName().isEmpty()) {
            ArLog.log(ArLog.Normal, "%sFailed to add section '%s' to category '%s', already defined in category '%s'",
                    logPrefix, sectionName, categoryName, s.getCategoryName());
            return false;
        }
        if (s == null) {
            ArLog.log(ArLog.Verbose, "%sMaking new section '%s' in category '%s'", logPrefix, sectionName, categoryName);
            s = new ArConfigSection(sectionName, sectionDescription);
            sections.add(s);
        } else {
            s.setComment(sectionDescription);
        }
        s.setCategoryName(categoryName);
        List<String> inCategory = categoryToSections.computeIfAbsent(categoryName, c -> new ArrayList<>());
        if (inCategory.stream().noneMatch(sectionName::equalsIgnoreCase)) {
            inCategory.add(sectionName);
        }
        return true;
    }

    /** @return the categories sections were added to, sorted */
    public List<String> getCategoryNames() {
        return List.copyOf(categoryToSections.keySet());
    }

    /**
     * @param categoryName a category, or "" for none
     * @return the sections added to it, in order; for "", the sections in no category
     */
    public List<String> getSectionNamesInCategory(String categoryName) {
        if (categoryName == null || categoryName.isEmpty()) {
            return sections.stream().filter(s -> !s.getName().isEmpty() && s.getCategoryName().isEmpty())
                    .map(ArConfigSection::getName).toList();
        }
        return List.copyOf(categoryToSections.getOrDefault(categoryName, List.of()));
    }

    /** @param sectionName a section (made if new) @param comment its comment, written under its name */
    public void setSectionComment(String sectionName, String comment) {
        ArConfigSection s = findSection(sectionName);
        if (s == null) {
            ArLog.log(ArLog.Verbose, "%sMaking new section '%s' (for comment)", logPrefix, sectionName);
            sections.add(new ArConfigSection(sectionName, comment));
        } else {
            s.setComment(comment);
        }
    }

    /** @param sectionName a section (made if new) @param flags flags to add @return true */
    public boolean addSectionFlags(String sectionName, String flags) {
        ArConfigSection s = findSection(sectionName);
        if (s == null) {
            ArLog.log(ArLog.Verbose, "%sMaking new section '%s' (flags)", logPrefix, sectionName);
            s = new ArConfigSection(sectionName, null);
            sections.add(s);
        }
        return s.addFlags(flags);
    }

    /** @param sectionName a section @param flag a flag to take off @return false if there is no such section */
    public boolean remSectionFlag(String sectionName, String flag) {
        ArConfigSection s = findSection(sectionName);
        return s != null && s.remFlag(flag);
    }

    /** @param sectionName a name, any case ("" for the parameters of no section) @return the section, or null */
    public ArConfigSection findSection(String sectionName) {
        if (sectionName == null) {
            ArLog.log(ArLog.Normal, "ArConfig::findSection() cannot find NULL section name");
            return null;
        }
        for (ArConfigSection s : sections) {
            if (s.getName().equalsIgnoreCase(sectionName)) {
                return s;
            }
        }
        return null;
    }

    /** @return the sections, in the order made: the list itself (change it only if you know what to do) */
    public List<ArConfigSection> getSections() {
        return sections;
    }

    /** @return the sections' names, in order (the section of no name left out, as ARIA's) */
    public List<String> getSectionNames() {
        return sections.stream().map(ArConfigSection::getName).filter(n -> !n.isEmpty()).toList();
    }

    /** Forgets the sections and their parameters. */
    public void clearSections() {
        sections.clear();
        paramNames.clear();
        categoryToSections.clear();
    }

    /** Forgets the sections and the process-file callbacks. */
    public void clearAll() {
        clearSections();
        processFileCBs.clear();
    }

    /**
     * Adds a callback run after a file is read, as ARIA's {@code addProcessFileCB}: higher
     * priorities first, equal ones in the order added.
     *
     * @param functor  returns false if the values read will not do
     * @param priority its place
     */
    public void addProcessFileCB(BooleanSupplier functor, int priority) {
        insert(new ProcessFileCB(functor, priority, buffer -> functor.getAsBoolean()));
    }

    /** @param functor a process-file callback, at priority 0 */
    public void addProcessFileCB(BooleanSupplier functor) {
        addProcessFileCB(functor, 0);
    }

    /**
     * ARIA's {@code addProcessFileWithErrorCB}: a callback that may put its reason for refusing
     * the values in the error buffer (which may be null).
     *
     * @param functor  returns false if the values read will not do
     * @param priority its place (higher first)
     */
    public void addProcessFileWithErrorCB(Predicate<StringBuilder> functor, int priority) {
        insert(new ProcessFileCB(functor, priority, functor));
    }

    private void insert(ProcessFileCB cb) {
        int at = 0;
        while (at < processFileCBs.size() && processFileCBs.get(at).priority() >= cb.priority()) {
            at++;
        }
        processFileCBs.add(at, cb);
    }

    /** @param functor a process-file callback to forget (each time it was added) */
    public void remProcessFileCB(Object functor) {
        processFileCBs.removeIf(cb -> cb.functor() == functor);
    }

    /**
     * For classes that extend ArConfig: called after the process-file callbacks, ARIA's {@code
     * processFile}.
     *
     * @return false if the values read will not do
     */
    protected boolean processFile() {
        return true;
    }

    /** @param continueOnErrors whether to go on after a callback fails @return false if one failed */
    public boolean callProcessFileCallBacks(boolean continueOnErrors) {
        return callProcessFileCallBacks(continueOnErrors, null, 0);
    }

    /**
     * Runs the process-file callbacks, as after a file is read: ARIA's {@code
     * callProcessFileCallBacks}. The error buffer is emptied and gets the first reason given.
     *
     * @param continueOnErrors whether to go on after a callback fails
     * @param errorBuffer      gets the first failing callback's reason, or null
     * @param errorBufferLen   the buffer's size as C's (0: any)
     * @return false if a callback or {@link #processFile} failed
     */
    public boolean callProcessFileCallBacks(boolean continueOnErrors, StringBuilder errorBuffer, int errorBufferLen) {
        boolean ret = true;
        ArLog.LogLevel level = processFileCallbacksLogLevel;
        section = "";
        StringBuilder buffer = errorBuffer;
        if (buffer != null) {
            buffer.setLength(0);
        }
        ArLog.log(level, "%sProcessing file", logPrefix);
        for (ProcessFileCB cb : List.copyOf(processFileCBs)) {
            ArLog.log(level, "%sProcessing unnamed functor (%d)", logPrefix, cb.priority());
            if (!cb.call().test(buffer)) {
                if (buffer != null && buffer.length() > 0) {
                    ConfigText.putError(buffer, errorBufferLen, buffer.toString());
                    buffer = null;
                }
                ret = false;
                if (!continueOnErrors) {
                    ArLog.log(ArLog.Normal, "ArConfig: Failed, stopping because unnamed process file callback failed");
                    break;
                }
                ArLog.log(ArLog.Normal, "ArConfig: Failed but continuing, an unnamed process file callback failed");
            }
        }
        if (ret || continueOnErrors) {
            ArLog.log(level, "%sProcessing with own processFile", logPrefix);
            if (!processFile()) {
                ret = false;
            }
        }
        ArLog.log(level, "%sDone processing file, ret is %s", logPrefix, ret);
        return ret;
    }

    /** @param fileName a file to read, stopping at the first error @return whether it was read and processed */
    public boolean parseFile(String fileName) {
        return parseFile(fileName, false, false, null, 0);
    }

    /** @param fileName a file to read @param continueOnErrors whether to go on after an error @return success */
    public boolean parseFile(String fileName, boolean continueOnErrors) {
        return parseFile(fileName, continueOnErrors, false, null, 0);
    }

    /**
     * Reads a configuration file into the parameters, then (if it was read, or {@code
     * continueOnErrors}) the argument parser given to {@link #useArgumentParser}, then runs the
     * process-file callbacks: ARIA's {@code ArConfig::parseFile}. A file that cannot be read is
     * logged ("ArFileParser::parseFile: Could not open file NAME to parse file.") unless {@code
     * noFileNotFoundMessage}; a refused value is logged with "## Last error on line N of file
     * 'NAME'".
     *
     * @param fileName              the file, under the base directory unless it starts with '/'
     * @param continueOnErrors      whether to go on after an error (the callbacks still run)
     * @param noFileNotFoundMessage whether a missing file goes unlogged
     * @param errorBuffer           emptied, then given the first callback's reason, or null
     * @param errorBufferLen        the buffer's size as C's (0: any)
     * @return false if the file could not be read, a value was refused or a callback failed
     */
    public boolean parseFile(String fileName, boolean continueOnErrors, boolean noFileNotFoundMessage,
            StringBuilder errorBuffer, int errorBufferLen) {
        this.fileName = fileName == null ? "" : fileName;
        ArLog.log(processFileCallbacksLogLevel, "Starting parsing file %s (%s)", this.fileName, fileName);
        if (errorBuffer != null) {
            errorBuffer.setLength(0);
        }
        boolean ret = new ConfigReader(this).parseFile(realFileName(this.fileName), continueOnErrors,
                noFileNotFoundMessage);
        if (argumentParser != null && (ret || continueOnErrors)) {
            ret = parseArgumentParser(argumentParser, continueOnErrors, unfilled(errorBuffer), errorBufferLen) && ret;
        }
        if (ret || continueOnErrors) {
            ret = callProcessFileCallBacks(continueOnErrors, unfilled(errorBuffer), errorBufferLen) && ret;
        }
        ArLog.log(processFileCallbacksLogLevel, "Done parsing file %s (ret %s)", fileName, ret);
        return ret;
    }

    private static StringBuilder unfilled(StringBuilder buffer) {
        return buffer != null && buffer.length() == 0 ? buffer : null;
    }

    private String realFileName(String name) {
        return name.startsWith("/") || name.startsWith("\\") ? name : baseDirectory + name;
    }

    /** @param fileName a file to write, replacing it @return false (logged) if it could not be written */
    public boolean writeFile(String fileName) {
        return writeFile(fileName, false);
    }

    /**
     * Writes the parameters in ARIA's form: {@code ConfigVersion 2.0}, the parameters of no
     * section, then each section ({@code Section NAME}, its comment, {@code ;SectionFlags for
     * NAME: flags}, its parameters with their values, bounds and descriptions), a blank line
     * between sections: ARIA's {@code ArConfig::writeFile}.
     *
     * @param fileName the file, under the base directory unless it starts with '/'
     * @param append   whether to add to the end of the file rather than replace it
     * @return false (logged: "Cannot open file 'NAME' for writing") if it could not be written
     */
    public boolean writeFile(String fileName, boolean append) {
        String real = realFileName(fileName);
        try (Writer w = new OutputStreamWriter(new FileOutputStream(real, append), StandardCharsets.UTF_8)) {
            w.write(ConfigText.write(sections, noBlanksBetweenParams));
            return true;
        } catch (IOException e) {
            ArLog.log(ArLog.Terse, "%sCannot open file '%s' for writing", logPrefix, real);
            return false;
        }
    }

    /** @param parser an argument parser whose parameters {@link #parseFile} reads after the file, or null */
    public void useArgumentParser(ArArgumentParser parser) {
        argumentParser = parser;
    }

    /** @param parser command-line arguments naming parameters @return false if a value was refused */
    public boolean parseArgumentParser(ArArgumentParser parser) {
        return parseArgumentParser(parser, false, null, 0);
    }

    /**
     * Sets parameters from command-line arguments ({@code Name value} or {@code -Name value}, any
     * case), taking both off the parser: ARIA's {@code ArConfig::parseArgumentParser}.
     *
     * @param parser          the arguments
     * @param continueOnError whether to go on after a refused value
     * @param errorBuffer     given the first refused value's reason, or null
     * @param errorBufferLen  the buffer's size as C's (0: any)
     * @return false if a value was refused
     */
    public boolean parseArgumentParser(ArArgumentParser parser, boolean continueOnError, StringBuilder errorBuffer,
            int errorBufferLen) {
        return new ConfigReader(this).parseArgumentParser(parser, continueOnError, errorBuffer, errorBufferLen);
    }

    /** @return the file last given to {@link #parseFile} */
    public String getFileName() {
        return fileName;
    }

    /** @return where relative file names are ("" for the working directory) */
    public String getBaseDirectory() {
        return baseDirectory;
    }

    /** @param baseDirectory put before relative file names as given (so it ends with '/'), or null */
    public void setBaseDirectory(String baseDirectory) {
        this.baseDirectory = baseDirectory == null ? "" : baseDirectory;
    }

    /** @param noBlanks whether the written file has no blank line after each parameter */
    public void setNoBlanksBetweenParams(boolean noBlanks) {
        noBlanksBetweenParams = noBlanks;
    }

    /** @return whether the written file has no blank line after each parameter */
    public boolean getNoBlanksBetweenParams() {
        return noBlanksBetweenParams;
    }

    /** @param save whether parameters and sections nobody added are kept and written back */
    public void setSaveUnknown(boolean save) {
        saveUnknown = save;
    }

    /** @return whether parameters and sections nobody added are kept */
    public boolean getSaveUnknown() {
        return saveUnknown;
    }

    /** @param level the level reading and processing are logged at (ARIA's default: Verbose) */
    public void setProcessFileCallbacksLogLevel(ArLog.LogLevel level) {
        processFileCallbacksLogLevel = level;
    }

    /** @return the level reading and processing are logged at */
    public ArLog.LogLevel getProcessFileCallbacksLogLevel() {
        return processFileCallbacksLogLevel;
    }
}
