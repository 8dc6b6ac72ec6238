package robosim.aria;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import java.util.logging.Level;
import java.util.logging.Logger;
import robosim.map.MapFileException;
import robosim.map.MapReader;

/**
 * ARIA's {@code ArMap} (ArMap.h, ArMapInterface.h, ArMap.cpp, ArMapComponents.cpp): a
 * MobileRobots {@code .map} file read into a robot program, so that it can plan on the map it runs
 * in: its objects ({@link ArMapObject}: goals, docks, robot homes, forbidden lines and areas), its
 * lines ({@link ArLineSegment}) and points, their bounds, its resolution and its {@code MapInfo:}
 * lines. The file is read by the same reader as the Environment's map worlds
 * ({@code robosim.map.MapReader}), so a map means the same to the world and to the program.
 *
 * <p>{@link #readFile(String)} reads the whole file or nothing: on any error it logs one line naming
 * the file, the line and the rule, keeps the map it had, and answers false. As in ARIA, it then
 * runs the map-changed callbacks whether it succeeded or not ({@code ArMap::readFile}). A map
 * holds one scan, ARIA's default ({@code ARMAP_DEFAULT_SCAN_TYPE}); ARIA's other scan types, its
 * change details and its writing back are not kept.
 */
public class ArMap {
    private static final Logger LOG = Logger.getLogger(ArMap.class.getName());

    private final ReentrantLock mutex = new ReentrantLock();
    private final List<Runnable> mapChangedCBs = new ArrayList<>();
    private String baseDirectory;
    private volatile String fileName = "";
    /** Replaced whole by a read, so that another thread sees one map or the other, never half. */
    private volatile MapContents contents = MapContents.EMPTY;

    /** A map whose files are found from the working directory ({@code ./}, ARIA's default). */
    public ArMap() {
        this("./");
    }

    /**
     * @param baseDirectory where a file name that is not absolute is found from; null or empty:
     *                      the file name as given
     */
    public ArMap(String baseDirectory) {
        this.baseDirectory = baseDirectory != null ? baseDirectory : "";
    }

    /**
     * Reads a map file, replacing what the map held, as ARIA's {@code readFile}. A file name that
     * is not absolute is found from the base directory ({@code ArMapInterface::createRealFileName}).
     *
     * @param fileName the map file
     * @return true if it was read; false, with a log line naming the file, the line and the rule,
     *         if it is missing or breaks a rule of the format (the map is then left as it was)
     */
    public boolean readFile(String fileName) {
        ArLog.log(ArLog.Normal, "ArMap::readFile() %s", fileName);
        boolean ok = false;
        lock();
        try {
            if (fileName == null || fileName.isEmpty()) {
                ArLog.log(ArLog.Terse, "ArMap::readFile: no file name given: name the .map file to read");
            } else {
                contents = MapContents.of(MapReader.read(Path.of(createRealFileName(fileName))));
                this.fileName = fileName;
                ok = true;
            }
        } catch (MapFileException e) {
            ArLog.log(ArLog.Terse, "ArMap::readFile: %s", e.getMessage());
        } catch (InvalidPathException e) {
            // a name no file can have is a failed read, as a missing file is
            ArLog.log(ArLog.Terse, "ArMap::readFile: %s: %s", fileName, e.getMessage());
        } finally {
            unlock();
        }
        mapChanged();
        return ok;
    }

    /**
     * @param fileName a map file's name
     * @return its path: as given when absolute or when there is no base directory, else under the
     *         base directory (ARIA's {@code createRealFileName})
     */
    public String createRealFileName(String fileName) {
        if (fileName.startsWith("/") || fileName.startsWith("\\") || baseDirectory.isEmpty()
                || Path.of(fileName).isAbsolute()) {
            return fileName;
        }
        return baseDirectory.endsWith("/") || baseDirectory.endsWith("\\") ? baseDirectory + fileName
                : baseDirectory + "/" + fileName;
    }

    /** @return the name the last file read was given to {@link #readFile(String)} with, or an empty string */
    public String getFileName() {
        return fileName;
    }

    /** @return where file names that are not absolute are found from */
    public String getBaseDirectory() {
        return baseDirectory;
    }

    /** @param baseDirectory where file names that are not absolute are found from from now on; null: none */
    public void setBaseDirectory(String baseDirectory) {
        this.baseDirectory = baseDirectory != null ? baseDirectory : "";
    }

    /** @return the map's objects, in file order; not to be changed */
    public List<ArMapObject> getMapObjects() {
        return contents.objects();
    }

    /**
     * @param name an object's name, compared ignoring case; null matches any
     * @return the first object of that name, of any type, or null (ARIA's {@code findMapObject})
     */
    public ArMapObject findMapObject(String name) {
        return findMapObject(name, null, false);
    }

    /**
     * @param name an object's name, compared ignoring case; null matches any
     * @param type its type, compared ignoring case; null matches any
     * @return the first object of that name and type, or null
     */
    public ArMapObject findMapObject(String name, String type) {
        return findMapObject(name, type, false);
    }

    /**
     * As ARIA's {@code ArMapObjects::findMapObject}.
     *
     * @param name                 an object's name, compared ignoring case; null matches any
     * @param type                 its type, compared ignoring case; null matches any
     * @param isIncludeWithHeading whether {@code type} is matched against the objects' base types,
     *                             so that {@code Goal} finds {@code GoalWithHeading} too
     * @return the first object that matches, in file order, or null
     */
    public ArMapObject findMapObject(String name, String type, boolean isIncludeWithHeading) {
        for (ArMapObject obj : contents.objects()) {
            if (matches(obj, type, isIncludeWithHeading) && (name == null || obj.getName().equalsIgnoreCase(name))) {
                return obj;
            }
        }
        return null;
    }

    /**
     * @param name an object's name, compared ignoring case; null matches any
     * @param type its type, compared ignoring case; null matches any
     * @return the first object of that name and type, or null (ARIA's {@code findFirstMapObject})
     */
    public ArMapObject findFirstMapObject(String name, String type) {
        return findMapObject(name, type, false);
    }

    /**
     * @param name                 an object's name; null matches any
     * @param type                 its type; null matches any
     * @param isIncludeWithHeading whether {@code type} is matched against the base types
     * @return the first object that matches, or null
     */
    public ArMapObject findFirstMapObject(String name, String type, boolean isIncludeWithHeading) {
        return findMapObject(name, type, isIncludeWithHeading);
    }

    /**
     * @param type a type, compared ignoring case; null matches any
     * @return the objects of that type, in file order (ARIA's {@code findMapObjectsOfType})
     */
    public List<ArMapObject> findMapObjectsOfType(String type) {
        return findMapObjectsOfType(type, false);
    }

    /**
     * @param type                 a type, compared ignoring case; null matches any
     * @param isIncludeWithHeading whether {@code type} is matched against the base types
     * @return the objects of that type, in file order
     */
    public List<ArMapObject> findMapObjectsOfType(String type, boolean isIncludeWithHeading) {
        List<ArMapObject> found = new ArrayList<>();
        for (ArMapObject obj : contents.objects()) {
            if (matches(obj, type, isIncludeWithHeading)) {
                found.add(obj);
            }
        }
        return found;
    }

    private static boolean matches(ArMapObject obj, String type, boolean isIncludeWithHeading) {
        return type == null || (isIncludeWithHeading ? obj.getBaseType() : obj.getType()).equalsIgnoreCase(type);
    }

    /** @return the map's points, in file order, heading 0; not to be changed */
    public List<ArPose> getPoints() {
        return contents.points();
    }

    /** @return the map's lines, in file order; not to be changed */
    public List<ArLineSegment> getLines() {
        return contents.lines();
    }

    /** @return the number of points read */
    public int getNumPoints() {
        return contents.points().size();
    }

    /** @return the number of lines read */
    public int getNumLines() {
        return contents.lines().size();
    }

    /**
     * @return the lower left corner of the points: the header's {@code MinPos} (else (0, 0), as
     *         ARIA starts from) lowered by every point read; with {@code NumPoints: 0},
     *         (INT_MAX, INT_MAX) as ARIA answers for no points
     */
    public ArPose getMinPose() {
        return new ArPose(contents.minPose());
    }

    /** @return the upper right corner of the points, as {@link #getMinPose()} (INT_MIN for no points) */
    public ArPose getMaxPose() {
        return new ArPose(contents.maxPose());
    }

    /** @return the lower left corner of the lines, as {@link #getMinPose()} does for the points, from {@code LineMinPos} */
    public ArPose getLineMinPose() {
        return new ArPose(contents.lineMinPose());
    }

    /** @return the upper right corner of the lines, from {@code LineMaxPos} */
    public ArPose getLineMaxPose() {
        return new ArPose(contents.lineMaxPose());
    }

    /** @return the header's {@code Resolution}, mm, or 0 when it has none (as ARIA's {@code ArMapScan} starts) */
    public int getResolution() {
        return contents.resolution();
    }

    /**
     * @return the values of the map's {@code MapInfo:} lines, in file order (ARIA answers each as an
     *         {@code ArArgumentBuilder}; here each is its text, for example {@code GoalType Name=Goal})
     */
    public List<String> getMapInfo() {
        return contents.mapInfo();
    }

    /**
     * @return the types of the map's objects, each once, in the order they first appear (the types
     *         a program may pass to {@link #findMapObjectsOfType(String)})
     */
    public List<String> getMapObjectTypes() {
        List<String> types = new ArrayList<>();
        for (ArMapObject obj : contents.objects()) {
            if (!types.contains(obj.getType())) {
                types.add(obj.getType());
            }
        }
        return types;
    }

    /** @param functor run after each {@link #readFile(String)}, after those added before (ARIA's {@code addMapChangedCB}) */
    public void addMapChangedCB(Runnable functor) {
        addMapChangedCB(functor, ArListPos.LAST);
    }

    /**
     * @param functor  run after each {@link #readFile(String)}
     * @param position {@link ArListPos#FIRST} to run before the others, {@link ArListPos#LAST} after;
     *                 any other position is refused with a log line
     */
    public void addMapChangedCB(Runnable functor, int position) {
        synchronized (mapChangedCBs) {
            if (functor == null) {
                ArLog.log(ArLog.Terse, "ArMap::addMapChangedCB: no callback given, ignoring it");
            } else if (position == ArListPos.FIRST) {
                mapChangedCBs.add(0, functor);
            } else if (position == ArListPos.LAST) {
                mapChangedCBs.add(functor);
            } else {
                ArLog.log(ArLog.Terse, "ArMap::addMapChangedCB: Invalid position %d: it must be ArListPos.FIRST (%d)"
                        + " or ArListPos.LAST (%d)", position, ArListPos.FIRST, ArListPos.LAST);
            }
        }
    }

    /** @param functor a callback added before; it runs no more */
    public void remMapChangedCB(Runnable functor) {
        synchronized (mapChangedCBs) {
            mapChangedCBs.remove(functor);
        }
    }

    /** Runs the map-changed callbacks, in order; one that throws is logged and the others still run. */
    public void mapChanged() {
        List<Runnable> copy;
        synchronized (mapChangedCBs) {
            copy = List.copyOf(mapChangedCBs);
        }
        for (Runnable r : copy) {
            try {
                r.run();
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "a map-changed callback of " + fileName + " threw", e);
            }
        }
    }

    /** Locks the map against another thread's {@link #readFile(String)}, as ARIA's {@code lock}. */
    public void lock() {
        mutex.lock();
    }

    /** @return whether the map was free and is now locked (ARIA's {@code tryLock}) */
    public boolean tryLock() {
        return mutex.tryLock();
    }

    /** Unlocks the map. */
    public void unlock() {
        mutex.unlock();
    }
}
