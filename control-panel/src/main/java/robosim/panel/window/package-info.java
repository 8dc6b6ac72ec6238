/**
 * The ControlPanel's window: thin Swing parts over {@link robosim.panel.model} (what is shown and
 * sent) and {@link robosim.panel.net.PanelSession} (the network, never on the event thread), with
 * viewer2d's live view embedded.
 */
package robosim.panel.window;
