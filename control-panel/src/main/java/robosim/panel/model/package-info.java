/**
 * The ControlPanel's logic, apart from Swing so that it is tested headless: what the robot table
 * shows from a {@link robosim.protocol.RunStatus}, what each button sends, and the checks on what
 * the user types (seed, ports, pace, poses, robot programs) before anything is sent or started.
 */
package robosim.panel.model;
