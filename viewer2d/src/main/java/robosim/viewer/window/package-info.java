/**
 * The Swing window: a live view of a running Environment, or a replay with play, pause, step and
 * a speed control. Split by panel: {@link robosim.viewer.window.WorldView} draws the world through
 * the same renderers as the PNG files (2D or 3D) and handles zoom, pan and camera drags;
 * {@link robosim.viewer.window.DisplayControls} toggles what is shown and which robot to follow;
 * {@link robosim.viewer.window.PlaybackControls} drives a {@link robosim.viewer.window.ReplayPlayer};
 * {@link robosim.viewer.window.StatusBar} shows the step and simulated time;
 * {@link robosim.viewer.window.ViewerPane} puts them together and
 * {@link robosim.viewer.window.ViewerWindow} puts the pane in a frame.
 *
 * <p>The state behind them ({@link robosim.viewer.window.ViewModel},
 * {@link robosim.viewer.window.ViewState}) is plain Java, and every panel paints off-screen, so
 * the window is tested headless. All of it runs on the Swing event thread;
 * {@link robosim.viewer.window.LiveFeed} carries snapshots there from the network thread.
 */
package robosim.viewer.window;
