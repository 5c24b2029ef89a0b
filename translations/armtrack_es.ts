<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es" sourcelanguage="en">
<context>
    <name>QObject</name>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopping...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reconnecting: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no data for %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>waiting for data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>streaming, losing samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>streaming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All devices are streaming</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui</name>
    <message>
        <source>Sit upright. Let the upper arm hang at the side, bend the elbow to a right angle, forearm pointing straight forward, thumb up. Keep still.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start pose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold still.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elbow bends</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bend and straighten the elbow four times, turning the palm down while straightening and up while bending.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder rotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elbow at a right angle: swing the hand in to the belly and out, three times.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reach and mouth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reach forward and up, then bring the hand to the mouth; three times.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm out and across</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lift the arm out to the side, then bring it back across; three times.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back to the start pose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The fit did not settle. Check that both sensors are strapped tight, then redo the protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The movements do not fit the arm model well (%1 off by %2 noise levels). Check the straps and the start pose, then redo the protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Usable, not perfect (worst: %1 at %2 noise levels).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo the protocol for a better one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Good: the data fit the arm model to the sensors&apos; noise level (worst: %1 at %2).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CalibrationGuide</name>
    <message>
        <source>Arm forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Raise the arm forward to shoulder height, elbow almost straight.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm to the side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lift the arm out to the side, about 60 degrees, elbow almost straight.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hand across</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bring the hand across the body, elbow at a right angle, palm down.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hand out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take the hand out to the side, elbow bent, palm up.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CameraCalibrationPage</name>
    <message>
        <source>Camera calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting the camera…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold the printed chessboard (%1 x %2 inner corners) in front of the camera. Capture views with the board in every part of the picture, near and far, tilted a little.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capture &amp;automatically when the board covers new ground</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Capture view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ca&amp;librate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start over</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera calibration verdict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check that the camera is plugged in and not used by another program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not calibrate: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reprojection error %1 px over %2 views; fx %3, fy %4 px.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Good.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Usable; more views, sharper and better lit, would improve it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Poor: capture the views again, holding the board still and flat.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The boards covered only %1 % of the picture; views near the edges help most.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capture at least 4 views first (%1 so far); 10 or more spread over the picture give a good calibration.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibrating…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 views kept; the boards cover %2 % of the picture.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CameraCalibrationWorker</name>
    <message>
        <source>No picture from the camera.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CsvRecordingTarget</name>
    <message>
        <source>a recording with this name exists; choose another name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 rows recorded in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 rows recorded in %2; some rows could not be written</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::DatabaseRecordingTarget</name>
    <message>
        <source>the records of patient %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot record into the records: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>session %1: %2 rows recorded, but it could not be closed: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>session %1 saved in the records: %2 rows</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::DevicesPage</name>
    <message>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Devices found (tick the ones to use):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device plugins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not loaded: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Check connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the devices, then check their connection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The devices could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not found: %1. Check the plugin folders in the settings.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tick at least one device first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop &amp;check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting the devices…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Receiving from every device…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not every device is streaming: %1. Check that each is switched on, charged and within range, then check again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check stopped.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::LiveSessionScreen</name>
    <message>
        <source>Live session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. The session goes on with the other sensors; check the device (power, cable or distance).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live session, %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start or resume recording (Ctrl+R)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause recording; the live view goes on (Ctrl+P)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End the session (Ctrl+E)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fatigue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Event label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Mark event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mark the chosen event at the current time (Ctrl+M)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Problem</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Try &amp;again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not start the session: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording resumed at %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording paused at %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Events: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last recording problem: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session ended; nothing was recorded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 marked at %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start or resume recording to %1 (Ctrl+R)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This session is not recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live %1 (not recording)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>● Recording %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused (%1 recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ended</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not running</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::SensorCalibrationPage</name>
    <message>
        <source>upper-arm gyroscope</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>upper-arm accelerometer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>forearm gyroscope</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>forearm accelerometer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>optical positions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sensor calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The patient sits upright with both sensors strapped on. Press Start, then follow the instructions for about a minute (docs/calibration.md).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time left in this step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protocol progress</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;ancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration verdict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The devices could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The protocol could not be recorded: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no data arrived</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting the sensors…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold still: %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move: %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The patient can relax.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibrating…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fitting the sensors&apos; mounting to the recording (this takes a few seconds).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The calibration failed: %1. Redo the protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper-arm strap angle %1 deg, forearm strap angle %2 deg; residuals (noise levels): upper gyro %3, upper acc %4, forearm gyro %5, forearm acc %6, optical %7; %8 iterations.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled. Press Start to begin the protocol again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::SessionController</name>
    <message>
        <source>a session is already running; stop it first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no device chosen: choose at least one device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no device plugin &quot;%1&quot;; found: %2. Check the plugin folders in the settings.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the session could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui</name>
    <message>
        <source>Usage: armtrack [options]

ArmTrack measures how a patient&apos;s arm moves during rehabilitation.

Options:
  --db URL        the clinical records to open: a file path, sqlite:PATH or
                  postgresql://user@host:port/dbname (default: armtrack.db in the
                  data folder chosen at the first start)
  --demo          open a demo database (made afresh) as a demo therapist and start a
                  live session with the virtual arm
  --plugins DIR   also look for device plugins in DIR (repeatable)
  --lang CODE     language of the user interface, e.g. en, de, es
  --quit-after S  quit after S seconds (for unattended runs)
  --screenshot FILE
                  with --quit-after: save the window as a PNG before quitting
  --version       print the version and exit
  --help          print this text and exit

Without a display, run it under a virtual one:
  xvfb-run -a -s &apos;-screen 0 1280x800x24&apos; armtrack --demo
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--quit-after: expected a positive number of seconds, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown option or argument &apos;%1&apos; (see armtrack --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--screenshot needs --quit-after</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To run ArmTrack on a machine without a screen, start it under a virtual display:
  xvfb-run -a -s &apos;-screen 0 1280x800x24&apos; armtrack --demo
(xvfb-run comes with the Debian package xvfb.) The clinical records can also be reached without a display through armtrack-cli.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ArmTrack cannot open the display &quot;%1&quot; (DISPLAY): no X server answers there.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ArmTrack needs a graphical display and found none (neither DISPLAY nor WAYLAND_DISPLAY is set).
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the patient a code, e.g. P001: it names the patient in files and exports.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The code may hold letters, digits, &apos;-&apos; and &apos;_&apos; (at most 32, starting with a letter or digit): &quot;%1&quot; does not.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the patient&apos;s name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The birth date is not a date.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The birth date lies in the future.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The birth date is before 1900.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The %1 of %2 cm is outside %3-%4 cm: check the measurement.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>upper arm length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>forearm length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>upper-arm IMU distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>forearm IMU distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The upper-arm IMU sits farther from the shoulder than the elbow is: check both measurements.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The forearm IMU sits farther from the elbow than the wrist is: check both measurements.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::AngleNames</name>
    <message>
        <source>Shoulder flexion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::AppController</name>
    <message>
        <source>Preparing the demo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Making demo records in %1: three patients, two protocols and six weeks of sessions, simulated and analysed the way real ones are. This takes a few seconds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signing in as the demo therapist...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2, demo)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Demo records: accounts &quot;%1&quot; and &quot;%2&quot;, password &quot;%3&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The new records location is used at the next sign-in.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening the records</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analysing the session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Estimating the joint angles of session %1 again from its recording and computing its metrics...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session %1 is saved, but it could not be analysed: %2
You can re-estimate it from its review.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Review session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Back to the patient</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Skip the analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home exercises</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This is a home account. The guided home exercises it opens arrive in a later version of ArmTrack. Until then, your therapist records your sessions at the clinic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back the file up, then bring it up to date with: armtrack-cli db migrate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Install the newer ArmTrack that wrote it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The file was left untouched. Restore it from a backup, or choose another database in the settings.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the location in the settings (or --db) and that you may read and write it, then try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The records cannot be opened</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Try again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>administrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>therapist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>home account</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::FirstRunScreen</name>
    <message>
        <source>&amp;Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Create and sign in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Welcome to ArmTrack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ArmTrack keeps its patients, sessions and recordings in one database. Choose where it lives and create the administrator account; the administrator can then add the therapists&apos; accounts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where the data lives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The database given on the command line: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the data folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Administrator account</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Administrator name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>at least %n characters</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Password again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password &amp;again:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The records will be kept in %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where ArmTrack keeps its data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the folder where ArmTrack keeps its data.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the data folder as a full path, e.g. %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the administrator a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The password needs at least %n characters.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The two passwords differ. Type the same password twice.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Creating the records...</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MainWindow</name>
    <message>
        <source>Signed-in account</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;ArmTrack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Patients</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+,</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About ArmTrack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About ArmTrack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;ArmTrack %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Measures the shoulder&apos;s and elbow&apos;s joint angles from two wearable IMUs and a Kinect or webcam, for upper-limb rehabilitation.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signed in as %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ArmTrack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 - ArmTrack</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MessageLine</name>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MessageScreen</name>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Progress</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::NewSessionScreen</name>
    <message>
        <source>New session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start the live session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the sensors and their options, then check the connection: every stream should turn green and the angles move with the arm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sensor calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The patient holds and makes the movements shown; ArmTrack then works out how the sensors sit on the arm. About a minute.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skip the calibration (the measured segment lengths are used)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Camera calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold the printed chessboard in front of the webcam in different places and angles until the grid is covered.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No webcam among the devices: nothing to calibrate here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skip the camera calibration (use the camera&apos;s stored model)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::OutputsPanel</name>
    <message>
        <source>&amp;PDF report...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The session report: details, metrics, plots, repetitions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;SV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angles (deg) with their uncertainty, and a metrics table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open&amp;Sim .mot...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The clinical angles as an OpenSim motion file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;BIDS...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A BIDS motion data set: IMUs, optical data and angles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rec&amp;ording...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The raw recording in the open format, bit for bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last output</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientDialog</name>
    <message>
        <source>New patient</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit patient %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper arm length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper-arm IMU distance from the shoulder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm IMU distance from the elbow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e.g. P001</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Birth date</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Code:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Born:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Sex:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Affected &amp;side:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Diagnosis:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured segment lengths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Upper arm (shoulder to elbow):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Forearm (elbow to wrist):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper-arm IMU from the shoulder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm IMU from the elbow:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>N&amp;otes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saving...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> cm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not measured</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientListScreen</name>
    <message>
        <source>&amp;Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New patient...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patients</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Search:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>code, name, diagnosis...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search patients</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a patient (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading the patients...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No patients yet. Add the first with &quot;New patient&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No patients.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The patients could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A patient with the code %1 exists already. Choose another code, or cancel and open that patient from the list.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientScreen</name>
    <message>
        <source>&amp;New session...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Review session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Progress report (PDF)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit patient...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Back to patients</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Code:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Born:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sex:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Affected side:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagnosis:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Notes:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured segment lengths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper arm:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper-arm IMU:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm IMU:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home programme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Progress</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This patient could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n stored length(s) could not be read.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Per week</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the progress report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the progress report...</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Progress report written: %1 (%n page(s)).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The progress report could not be written: %1. Choose another folder or file name and try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 cm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record a new session with this patient (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target (°)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientTableModel</name>
    <message>
        <source>female</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>male</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diverse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Born</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ProgressChart</name>
    <message>
        <source>&amp;Angle:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle shown in the progress chart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Progress chart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range of motion per session against date; the table beside it holds the same values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Progress values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rad</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Date</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Of normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range of motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no analysed session yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ROM (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal (AAOS) %L1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>d MMM</source>
        <comment>the date axis&apos; labels, a QDateTime format: day and short month</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RecordsRecordingTarget</name>
    <message>
        <source>the records of patient %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RecordsService</name>
    <message>
        <source>The background connection to the records could not sign in (%1). Reports, exports and analyses will fail until you sign in again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ReestimatePanel</name>
    <message>
        <source>Fuse the &amp;optical data (Kinect, webcam)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B&amp;rowse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-&amp;estimate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shown:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EKF (extended Kalman filter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UKF (unscented Kalman filter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Filter:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A: body acceleration modelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B: body acceleration as states</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C: no compensation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none (a file from armtrack-cli calibrate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Calibration:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibrations (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RepetitionTableModel</name>
    <message>
        <source>partial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>full</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>#</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Excursion (rad)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range (rad)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak velocity (rad/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SPARC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Full or partial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Excursion (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range (°)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak velocity (°/s)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ReviewScreen</name>
    <message>
        <source>Review of session %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Back to the patient</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D arm replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Repetitions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session to compare with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another session of this patient, drawn dashed on the plots and as a translucent arm:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Co&amp;mpare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sa&amp;ve notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-es&amp;timate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Report and e&amp;xport</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the session...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This session could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: session of %2, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Review: %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not analysed yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This session has no analysis yet (it may have been cut short or failed). Open &quot;Re-estimate&quot; to estimate its joint angles from the recording.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 repetitions on %2 (%3 full, %4 partial). Smoothness: SPARC %5, LDLJ %6.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) could not be read.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>No metrics yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Notes typed earlier were not saved; they are back in the Notes tab. Save them or edit them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session %1 has no analysis to compare with. Review it and re-estimate it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>That session could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Notes saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The notes could not be saved: %1. They stay here and in a draft; try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Estimating the joint angles again...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-estimation cancelled; nothing was stored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New estimates stored as version %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The session could not be estimated again: %1. The earlier estimates are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the session report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder of the BIDS data set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export as OpenSim motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenSim motion (*.mot)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the angles as CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recordings (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the session report</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Session report written: %1 (%n page(s)).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>the export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing %1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 could not be written: %2. Choose another place and try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>version %1 of %2: %3, method %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, optical data fused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, no optical data fused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, calibrated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play or pause the replay (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1×</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SessionSetupPage</name>
    <message>
        <source>&amp;Left arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Right arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient, protocol and arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose what this session trains and which arm wears the sensors.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no protocol: free movement)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the patient and the protocols...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The patient or the protocols could not be read: %1. Go back and try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Note: this protocol is meant for the %1 arm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Trains %1, target %L2–%L3°, %n repetition(s).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SessionTableModel</name>
    <message>
        <source>complete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IMU samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Notes</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SettingsDialog</name>
    <message>
        <source>&amp;Add folder...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Display</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>radians</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle &amp;units:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as the system</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A&amp;ppearance:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data &amp;folder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>armtrack.db in the data folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A file path, sqlite:PATH, or postgresql://user@host:port/dbname</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Database</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Database:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device plugin folders (searched before the built-in ones)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plugin folders</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Estimation of new sessions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EKF (extended Kalman filter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UKF (unscented Kalman filter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default filter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F&amp;ilter:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A: body acceleration modelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B: body acceleration as states</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C: no compensation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plugin folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the data folder as a full path, e.g. %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The database location is not one ArmTrack understands: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The plugin folder %1 does not exist.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SignInScreen</name>
    <message>
        <source>&amp;Sign in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sign in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sign in to ArmTrack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Records: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Account name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type your account name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type your password.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signing in...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the name and the password (is Caps Lock on?) and try again. If you have forgotten it, an administrator can set a new one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Wait %n s</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Too many wrong passwords for this account: wait %n s, then try again.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Wrong user name or password.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::reports</name>
    <message>
        <source>time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>numbers: repetitions at their peaks (p = partial)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>angle (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>date</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>shaded: AAOS normal range of motion, 0-%L1 deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not measured in this period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Page %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Progress report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient and period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patient code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Date of birth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Therapist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range of motion over time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No sessions between %1 and %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: range of motion (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal ranges: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Date</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ROM in degrees (maximum minus minimum over the session).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2), progress %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>progress report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Progress report: %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder flexion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>either</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>female</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>male</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diverse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>complete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 UTC</source>
        <comment>a date and a time of day</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 - %2 - generated %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(not valid JSON: %1 at offset %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>... %n more</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %2, target %3 to %4 deg, %n repetitions</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Patient and session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Side measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices and calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No devices were recorded for this session.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No calibration was recorded for this session.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 not defined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Metrics per clinical angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ROM (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak velocity (deg/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean velocity (deg/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moving time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 samples used, %L2 rows rejected (not finite), %L3 gaps. Smoothness of the wrist path: %4, %5.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Joint angles over time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>shaded: protocol target %1 to %2 deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>p</source>
        <comment>a partial repetition&apos;s mark on the plot</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No repetitions were detected (0 repetitions).</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n repetitions counted on %1: %2 full, %3 partial (judged against a reference range of %4 deg); %5 cut by the start or end of the recording and not counted.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>#</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ROM of %1 (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Partial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comparison with normative ranges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ROM %1 of %2 deg (%L3 %)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grey: the normal active range of motion; blue: this session&apos;s range (negative = extension, external rotation, supination). Source: %1. Shoulder adduction has no normal limit in that source; its range is shown from 0.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comparison with earlier sessions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Range of motion (deg) of each angle per session.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 this session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change since last</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other side, %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No earlier sessions to compare with.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Therapist&apos;s notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No notes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2), session of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>session report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session report: %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session report</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleChart</name>
    <message>
        <source>Plot of %1 over time in degrees; the table beside it holds the same numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>଒σ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compared session</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AnglePlotPanel</name>
    <message>
        <source>Joint angle plots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Joint angles table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The current value of each angle, its uncertainty, the range over the plotted time and the target</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleReadouts</name>
    <message>
        <source>Current joint angles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uncertain (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uncertain</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleTableModel</name>
    <message>
        <source>Angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>଒σ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::Angles</name>
    <message>
        <source>Shoulder flexion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::ArmView</name>
    <message>
        <source>3D view of the arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The estimated arm with its sensors. Arrow keys turn the view, plus and minus zoom, Home resets the view.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drag to turn the view, scroll to zoom; Home resets it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right arm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceHealthModel</name>
    <message>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stream</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rejected</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceHealthPanel</name>
    <message>
        <source>Device health</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device health summary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices and streams</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceOptionsForm</name>
    <message>
        <source>Device options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(not set)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>armtrack::ui::RepetitionCounterWidget</name>
    <message>
        <source>Repetitions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repetitions done of the target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repetitions (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n partial</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>target reached</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
