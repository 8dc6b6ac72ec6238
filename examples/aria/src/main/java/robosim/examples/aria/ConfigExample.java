package robosim.examples.aria;

import java.util.function.BooleanSupplier;
import robosim.aria.ArArgumentParser;
import robosim.aria.ArConfig;
import robosim.aria.ArConfigArg;
import robosim.aria.ArConfigSection;
import robosim.aria.ArLog;
import robosim.aria.ArPriority;
import robosim.aria.Aria;

/**
 * ARIA's {@code configExample.cpp}, line for line: the use of {@link ArConfig} to keep parameters
 * and load and save them from a file. It adds four parameters to {@link Aria#getConfig()}, loads
 * the file given on the command line, flips the boolean parameter, runs the process-file callback
 * again and writes the file back.
 *
 * <p>Where the C++ gives {@code ArConfigArg} a pointer to its field, the port gives how to read the
 * field and how to set it ({@link ArConfigArg#ofInt} and the others); the error buffer is a
 * {@link StringBuilder}. Run it with {@code examples/aria/configExample.cfg}.
 */
public final class ConfigExample {
    private int myIntParam;
    private double myDoubleParam;
    private boolean myBoolParam;
    private String myStringParam;
    private final BooleanSupplier myProcessConfigCB;

    private ConfigExample() {
        myIntParam = 0;
        myDoubleParam = 0.5;
        myBoolParam = false;
        myProcessConfigCB = this::processConfigFile;

        // The global Aria class contains an ArConfig object.  You can create
        // other instances of ArConfig, but this is how you can share one ArConfig
        // among various program modules.
        // If you want to store a config parameter in ArConfig, first you must add
        // it to the ArConfig object.  Parameters are stored in sections, and
        // they affect a variable through how to read and set it, given to an
        // ArConfigArg object:
        ArConfig config = Aria.getConfig();
        config.setSectionComment("Example Section", "Contains parameters created by the configExample");

        // Add an integer which ranges from -10 to 10:
        config.addParam(ArConfigArg.ofInt("ExampleIntegerParameter", () -> myIntParam, v -> myIntParam = v,
                "Example parameter integer.", -10, 10), "Example Section", ArPriority.NORMAL);

        // Add a floating point number which ranges from 0.0 to 1.0:
        config.addParam(ArConfigArg.ofDouble("ExampleDoubleParameter", () -> myDoubleParam, v -> myDoubleParam = v,
                "Example double precision floating point number.", 0.0, 1.0), "Example Section", ArPriority.NORMAL);

        // Essential parameters can be placed in the "Important" priority level:
        config.addParam(ArConfigArg.ofBool("ExampleBoolParameter", () -> myBoolParam, v -> myBoolParam = v,
                "Example boolean parameter."), "Example Section", ArPriority.IMPORTANT);

        // Unimportant parameters can be placed in the "Trivial" priority level:
        myStringParam = ""; // make string empty
        config.addParam(ArConfigArg.ofString("ExampleStringParameter", () -> myStringParam, v -> myStringParam = v,
                "Example string parameter.", 256), "Example Section", ArPriority.TRIVIAL);

        // You can set a callback to be invoked when the configuration changes, in
        // case you need to respond to any changes in the parameter values:
        config.addProcessFileCB(myProcessConfigCB, 0);
    }

    // Method called by config process callback when a new file is loaded.
    // It can return false to indicate an error, or true to indicate no error.
    private boolean processConfigFile() {
        ArLog.log(ArLog.Normal, "configExample: Config changed. New values: int=%d, float=%f, bool=%s, string=\"%s\".",
                myIntParam, myDoubleParam, myBoolParam ? "true" : "false", myStringParam);
        return true;
    }

    /** @param args the config file to load, change and save */
    public static void main(String[] args) {
        Aria.init();
        ArArgumentParser argParser = new ArArgumentParser(args);
        argParser.loadDefaultArguments();
        if (argParser.getArgc() < 2 || !Aria.parseArgs() || argParser.checkArgument("-help")) {
            ArLog.log(ArLog.Terse, "configExample usage: configExample <config file>.\n"
                    + "For example, \"configExample examples/aria/configExample.cfg\".");
            Aria.logOptions();
            Aria.exit(1);
            return;
        }

        // Object containing config parameters, and responding to changes:
        ConfigExample configExample = new ConfigExample();

        // Load a config file given on the command line into the global
        // ArConfig object kept by Aria.  Relative file names are under
        // the config's base directory (Aria.setDirectory), the working
        // directory unless set.
        StringBuilder error = new StringBuilder();
        String filename = argParser.getArg(1);
        ArConfig config = Aria.getConfig();
        ArLog.log(ArLog.Normal, "configExample: loading configuration file \"%s\"...", filename);
        if (!config.parseFile(filename, true, false, error, 512)) {
            ArLog.log(ArLog.Terse, "configExample: Error loading configuration file \"%s\" %s. "
                    + "Try \"examples/aria/configExample.cfg\".", filename, error);
            Aria.exit(-1);
            return;
        }

        ArLog.log(ArLog.Normal, "configExample: Loaded configuration file \"%s\".", filename);

        ArConfigSection section = config.findSection("Example Section");
        if (section != null) {
            ArConfigArg arg = section.findParam("ExampleBoolParameter");
            if (arg != null) {
                arg.setBool(!arg.getBool());
                // After changing a config value, you should invoke the callbacks:
                if (!config.callProcessFileCallBacks(false, error, 512)) {
                    ArLog.log(ArLog.Terse, "configExample: Error processing modified config: %s.", error);
                } else {
                    ArLog.log(ArLog.Normal, "configExample: Successfully modified config and invoked callbacks.");
                }
            }
        }

        // You can save the configuration as well:
        ArLog.log(ArLog.Normal, "configExample: Saving configuration...");
        if (!config.writeFile(filename)) {
            ArLog.log(ArLog.Terse, "configExample: Error saving configuration to file \"%s\"!", filename);
        }

        // end of program.
        ArLog.log(ArLog.Normal, "configExample: end of program.");
        Aria.exit(0);
    }
}
