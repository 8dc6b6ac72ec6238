/**
 * The JVMs the ControlPanel starts: an Environment, robot programs and RemoteControl windows, each
 * {@code robosim.cli.Main} with a subcommand, their output fed line by line to the panel's log, and
 * stopped, with their children, when the panel asks or closes.
 */
package robosim.panel.process;
