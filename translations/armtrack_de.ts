<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>StrapsText</name>
    <message>
        <source>Straps checked from the movement: upper-arm sensor turned %1 deg, forearm sensor turned %2 deg and %3 cm from the wrist</source>
        <translation>Bänder anhand der Bewegung geprüft: Oberarmsensor um %1° gedreht, Unterarmsensor um %2° gedreht und %3 cm vom Handgelenk</translation>
    </message>
    <message>
        <source>Straps: not checked yet (the arm needs a moment of rest and more movement)</source>
        <translation>Bänder: noch nicht geprüft (der Arm braucht einen Moment Ruhe und mehr Bewegung)</translation>
    </message>
    <message>
        <source>Straps: checking them from the movement…</source>
        <translation>Bänder: werden anhand der Bewegung geprüft…</translation>
    </message>
    <message>
        <source>Straps as fitted (checked from the movement)</source>
        <translation>Bänder sitzen wie angelegt (anhand der Bewegung geprüft)</translation>
    </message>
    <message>
        <source>A sensor strap has turned on your arm. Your exercise is still measured; next time, put the straps on as shown before you start.</source>
        <translation>Ein Sensorband hat sich an Ihrem Arm verdreht. Ihre Übung wird trotzdem gemessen; legen Sie die Bänder nächstes Mal vor dem Start wie gezeigt an.</translation>
    </message>
    <message>
        <source>Straps: checking them from the movement (rest still a moment with the upper arm hanging, the elbow bent to a right angle and the thumb up, then move)</source>
        <translation>Bänder: werden anhand der Bewegung geprüft (einen Moment still ruhen, Oberarm hängend, Ellbogen rechtwinklig gebeugt, Daumen nach oben, dann bewegen)</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CalibrationGuide</name>
    <message>
        <source>Arm forward</source>
        <translation>Arm nach vorn</translation>
    </message>
    <message>
        <source>Raise the arm forward to shoulder height, elbow almost straight.</source>
        <translation>Den Arm nach vorn auf Schulterhöhe heben, den Ellenbogen fast gestreckt.</translation>
    </message>
    <message>
        <source>Arm to the side</source>
        <translation>Arm zur Seite</translation>
    </message>
    <message>
        <source>Lift the arm out to the side, about 60 degrees, elbow almost straight.</source>
        <translation>Den Arm seitlich etwa 60 Grad abspreizen, den Ellenbogen fast gestreckt.</translation>
    </message>
    <message>
        <source>Hand across</source>
        <translation>Hand zur Gegenseite</translation>
    </message>
    <message>
        <source>Bring the hand across the body, elbow at a right angle, palm down.</source>
        <translation>Die Hand vor dem Körper zur Gegenseite führen, Ellenbogen rechtwinklig, Handfläche nach unten.</translation>
    </message>
    <message>
        <source>Hand out</source>
        <translation>Hand nach außen</translation>
    </message>
    <message>
        <source>Take the hand out to the side, elbow bent, palm up.</source>
        <translation>Die Hand nach außen zur Seite führen, Ellenbogen gebeugt, Handfläche nach oben.</translation>
    </message>
    <message>
        <source>Sit upright. Let the upper arm hang at the side, bend the elbow to a right angle, forearm pointing straight forward, thumb up. Keep still.</source>
        <translation>Aufrecht sitzen. Den Oberarm seitlich hängen lassen, den Ellenbogen rechtwinklig beugen, der Unterarm zeigt gerade nach vorn, der Daumen nach oben. Ruhig halten.</translation>
    </message>
    <message>
        <source>Hold still.</source>
        <translation>Ruhig halten.</translation>
    </message>
    <message>
        <source>Start pose</source>
        <translation>Ausgangsstellung</translation>
    </message>
    <message>
        <source>Elbow bends</source>
        <translation>Ellenbogen beugen</translation>
    </message>
    <message>
        <source>Bend and straighten the elbow four times, turning the palm down while straightening and up while bending.</source>
        <translation>Den Ellenbogen viermal beugen und strecken; beim Strecken die Handfläche nach unten drehen, beim Beugen nach oben.</translation>
    </message>
    <message>
        <source>Shoulder rotation</source>
        <translation>Schulterrotation</translation>
    </message>
    <message>
        <source>Elbow at a right angle: swing the hand in to the belly and out, three times.</source>
        <translation>Ellenbogen rechtwinklig: die Hand dreimal zum Bauch hin und wieder nach außen schwenken.</translation>
    </message>
    <message>
        <source>Reach and mouth</source>
        <translation>Greifen und zum Mund</translation>
    </message>
    <message>
        <source>Reach forward and up, then bring the hand to the mouth; three times.</source>
        <translation>Nach vorn oben greifen, dann die Hand zum Mund führen; dreimal.</translation>
    </message>
    <message>
        <source>Arm out and across</source>
        <translation>Arm hinaus und zurück</translation>
    </message>
    <message>
        <source>Lift the arm out to the side, then bring it back across; three times.</source>
        <translation>Den Arm seitlich abspreizen und dann vor dem Körper zurückführen; dreimal.</translation>
    </message>
    <message>
        <source>Back to the start pose</source>
        <translation>Zurück in die Ausgangsstellung</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CameraCalibrationPage</name>
    <message>
        <source>Camera calibration</source>
        <translation>Kamerakalibrierung</translation>
    </message>
    <message>
        <source>Starting the camera…</source>
        <translation>Kamera wird gestartet …</translation>
    </message>
    <message>
        <source>Camera picture</source>
        <translation>Kamerabild</translation>
    </message>
    <message>
        <source>Hold the printed chessboard (%1 x %2 inner corners) in front of the camera. Capture views with the board in every part of the picture, near and far, tilted a little.</source>
        <translation>Das gedruckte Schachbrett (%1 × %2 innere Ecken) vor die Kamera halten. Ansichten aufnehmen, in denen das Brett in jedem Teil des Bildes liegt, nah und fern, leicht geneigt.</translation>
    </message>
    <message>
        <source>Capture &amp;automatically when the board covers new ground</source>
        <translation>&amp;Automatisch aufnehmen, wenn das Brett neue Bildbereiche abdeckt</translation>
    </message>
    <message>
        <source>&amp;Capture view</source>
        <translation>Ansicht auf&amp;nehmen</translation>
    </message>
    <message>
        <source>Ca&amp;librate</source>
        <translation>Ka&amp;librieren</translation>
    </message>
    <message>
        <source>&amp;Start over</source>
        <translation>&amp;Neu beginnen</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Abdeckung</translation>
    </message>
    <message>
        <source>Camera calibration verdict</source>
        <translation>Ergebnis der Kamerakalibrierung</translation>
    </message>
    <message>
        <source>Check that the camera is plugged in and not used by another program.</source>
        <translation>Prüfen Sie, ob die Kamera angeschlossen ist und von keinem anderen Programm benutzt wird.</translation>
    </message>
    <message>
        <source>Could not calibrate: %1</source>
        <translation>Kalibrierung nicht möglich: %1</translation>
    </message>
    <message>
        <source>Good.</source>
        <translation>Gut.</translation>
    </message>
    <message>
        <source>Usable; more views, sharper and better lit, would improve it.</source>
        <translation>Brauchbar; mehr Ansichten, schärfer und besser beleuchtet, würden sie verbessern.</translation>
    </message>
    <message>
        <source>Poor: capture the views again, holding the board still and flat.</source>
        <translation>Schlecht: die Ansichten neu aufnehmen und das Brett dabei ruhig und eben halten.</translation>
    </message>
    <message>
        <source>The boards covered only %1 % of the picture; views near the edges help most.</source>
        <translation>Die Bretter deckten nur %1 % des Bildes ab; Ansichten nahe den Rändern helfen am meisten.</translation>
    </message>
    <message>
        <source>Capture at least 4 views first (%1 so far); 10 or more spread over the picture give a good calibration.</source>
        <translation>Zuerst mindestens 4 Ansichten aufnehmen (bisher %1); 10 oder mehr, über das Bild verteilt, ergeben eine gute Kalibrierung.</translation>
    </message>
    <message>
        <source>Calibrating…</source>
        <translation>Kalibrierung läuft …</translation>
    </message>
    <message>
        <source>%1 views kept; the boards cover %2 % of the picture.</source>
        <translation>%1 Ansichten behalten; die Bretter decken %2 % des Bildes ab.</translation>
    </message>
    <message>
        <source>Reprojection error %L1 px over %2 views; fx %L3, fy %L4 px.</source>
        <translation>Rückprojektionsfehler %L1 px über %2 Ansichten; fx %L3, fy %L4 px.</translation>
    </message>
    <message>
        <source>No device among those chosen gives webcam images or marker pixels: nothing to calibrate here.</source>
        <translation>Keines der gewählten Geräte liefert Webcam-Bilder oder Markerpixel: hier gibt es nichts zu kalibrieren.</translation>
    </message>
    <message>
        <source>The webcam of %1 brings its own camera model (it is simulated or replayed), so there is no chessboard to show it: nothing to calibrate here.</source>
        <translation>Die Webcam von %1 bringt ihr eigenes Kameramodell mit (sie ist simuliert oder wiedergegeben), daher kann man ihr kein Schachbrett zeigen: hier gibt es nichts zu kalibrieren.</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CameraCalibrationWorker</name>
    <message>
        <source>No picture from the camera.</source>
        <translation>Kein Bild von der Kamera.</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::DevicesPage</name>
    <message>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <source>&amp;Devices found (tick the ones to use):</source>
        <translation>Gefundene &amp;Geräte (die zu verwendenden ankreuzen):</translation>
    </message>
    <message>
        <source>Device plugins</source>
        <translation>Geräte-Plugins</translation>
    </message>
    <message>
        <source>Not loaded: %1</source>
        <translation>Nicht geladen: %1</translation>
    </message>
    <message>
        <source>&amp;Check connection</source>
        <translation>Verbindung &amp;prüfen</translation>
    </message>
    <message>
        <source>Check connection</source>
        <translation>Verbindung prüfen</translation>
    </message>
    <message>
        <source>Choose the devices, then check their connection.</source>
        <translation>Geräte auswählen, dann ihre Verbindung prüfen.</translation>
    </message>
    <message>
        <source>Connection check</source>
        <translation>Verbindungsprüfung</translation>
    </message>
    <message>
        <source>The devices could not start: %1</source>
        <translation>Die Geräte konnten nicht starten: %1</translation>
    </message>
    <message>
        <source>Not found: %1. Check the plugin folders in the settings.</source>
        <translation>Nicht gefunden: %1. Prüfen Sie die Plugin-Ordner in den Einstellungen.</translation>
    </message>
    <message>
        <source>Tick at least one device first.</source>
        <translation>Zuerst mindestens ein Gerät ankreuzen.</translation>
    </message>
    <message>
        <source>Stop &amp;check</source>
        <translation>Prüfung &amp;beenden</translation>
    </message>
    <message>
        <source>Starting the devices…</source>
        <translation>Geräte werden gestartet …</translation>
    </message>
    <message>
        <source>Connected: %1.</source>
        <translation>Verbunden: %1.</translation>
    </message>
    <message>
        <source>Receiving from every device…</source>
        <translation>Daten kommen von allen Geräten …</translation>
    </message>
    <message>
        <source>Not every device is streaming: %1. Check that each is switched on, charged and within range, then check again.</source>
        <translation>Nicht alle Geräte senden: %1. Prüfen Sie, ob jedes eingeschaltet, geladen und in Reichweite ist, dann erneut prüfen.</translation>
    </message>
    <message>
        <source>Check stopped.</source>
        <translation>Prüfung beendet.</translation>
    </message>
    <message>
        <source>%1 %2 %L3 Hz</source>
        <translation>%1 %2 %L3 Hz</translation>
    </message>
    <message>
        <source>%1 %L2 % (low: charge it after the session)</source>
        <translation>%1 %L2 % (schwach: nach der Sitzung laden)</translation>
    </message>
    <message>
        <source>%1 %L2 %</source>
        <translation>%1 %L2 %</translation>
    </message>
    <message>
        <source>Battery: %1.</source>
        <translation>Akku: %1.</translation>
    </message>
    <message>
        <source>The angles keep following the arm: move it and check them, then go on (or stop the check).</source>
        <translation>Die Winkel folgen dem Arm weiter: bewegen Sie ihn und prüfen Sie sie, dann gehen Sie weiter (oder beenden Sie die Prüfung).</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::LiveSessionScreen</name>
    <message>
        <source>Live session</source>
        <translation>Live-Sitzung</translation>
    </message>
    <message>
        <source>%1. The session goes on with the other sensors; check the device (power, cable or distance).</source>
        <translation>%1. Die Sitzung läuft mit den anderen Sensoren weiter; prüfen Sie das Gerät (Strom, Kabel oder Abstand).</translation>
    </message>
    <message>
        <source>left arm</source>
        <translation>linker Arm</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>rechter Arm</translation>
    </message>
    <message>
        <source>Live session, %1</source>
        <translation>Live-Sitzung, %1</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>Session status</source>
        <translation>Sitzungsstatus</translation>
    </message>
    <message>
        <source>&amp;Record</source>
        <translation>Auf&amp;nehmen</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Pain</source>
        <translation>Schmerz</translation>
    </message>
    <message>
        <source>Rest</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Fatigue</source>
        <translation>Ermüdung</translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation>Kompensation</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Notiz</translation>
    </message>
    <message>
        <source>Event label</source>
        <translation>Ereignisbezeichnung</translation>
    </message>
    <message>
        <source>&amp;Mark event</source>
        <translation>Ereignis &amp;markieren</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>Problem</translation>
    </message>
    <message>
        <source>Try &amp;again</source>
        <translation>&amp;Erneut versuchen</translation>
    </message>
    <message>
        <source>Session messages</source>
        <translation>Sitzungsmeldungen</translation>
    </message>
    <message>
        <source>Could not start the session: %1</source>
        <translation>Die Sitzung konnte nicht starten: %1</translation>
    </message>
    <message>
        <source>Session started</source>
        <translation>Sitzung gestartet</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Aufnahme in %1</translation>
    </message>
    <message>
        <source>Last recording problem: %1</source>
        <translation>Letztes Aufnahmeproblem: %1</translation>
    </message>
    <message>
        <source>Session ended; nothing was recorded.</source>
        <translation>Sitzung beendet; nichts wurde aufgenommen.</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>Ereignis</translation>
    </message>
    <message>
        <source>Recording stopped: %1</source>
        <translation>Aufnahme angehalten: %1</translation>
    </message>
    <message>
        <source>This session is not recorded</source>
        <translation>Diese Sitzung wird nicht aufgenommen</translation>
    </message>
    <message>
        <source>Not started</source>
        <translation>Nicht gestartet</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Startet …</translation>
    </message>
    <message>
        <source>Live %1 (not recording)</source>
        <translation>Live %1 (keine Aufnahme)</translation>
    </message>
    <message>
        <source>● Recording %1</source>
        <translation>● Aufnahme %1</translation>
    </message>
    <message>
        <source>Paused (%1 recorded)</source>
        <translation>Pausiert (%1 aufgenommen)</translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation>Wird beendet …</translation>
    </message>
    <message>
        <source>Ended</source>
        <translation>Beendet</translation>
    </message>
    <message>
        <source>Not running</source>
        <translation>Läuft nicht</translation>
    </message>
    <message>
        <source>Live session: %1</source>
        <translation>Live-Sitzung: %1</translation>
    </message>
    <message>
        <source>Pause recording; the live view goes on (%1)</source>
        <translation>Aufnahme pausieren; die Live-Ansicht läuft weiter (%1)</translation>
    </message>
    <message>
        <source>End the session (%1)</source>
        <translation>Sitzung beenden (%1)</translation>
    </message>
    <message>
        <source>Mark the chosen event at the current time (%1)</source>
        <translation>Das gewählte Ereignis zum aktuellen Zeitpunkt markieren (%1)</translation>
    </message>
    <message>
        <source>Recording resumed at %L1 s</source>
        <translation>Aufnahme bei %L1 s fortgesetzt</translation>
    </message>
    <message>
        <source>Recording paused at %L1 s</source>
        <translation>Aufnahme bei %L1 s pausiert</translation>
    </message>
    <message>
        <source>%1 marked at %L2 s</source>
        <translation>%1 bei %L2 s markiert</translation>
    </message>
    <message>
        <source>Start or resume recording to %1 (%2)</source>
        <translation>Aufnahme in %1 starten oder fortsetzen (%2)</translation>
    </message>
    <message>
        <source>Straps</source>
        <translation>Bänder</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::LiveTrunkFeedback</name>
    <message>
        <source>Trunk: flexion %1, lateral bending %2, axial rotation %3</source>
        <translation>Rumpf: Flexion %1, Seitneigung %2, Rotation %3</translation>
    </message>
    <message>
        <source>The trunk moved: shoulder angles include the lean.</source>
        <translation>Der Rumpf hat sich bewegt: Die Schulterwinkel enthalten die Neigung.</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) with compensation</source>
        <translation>
            <numerusform>%n Wiederholung mit Kompensation</numerusform>
            <numerusform>%n Wiederholungen mit Kompensation</numerusform>
        </translation>
    </message>
    <message>
        <source>(trunk limit %1)</source>
        <translation>(Rumpfgrenze %1)</translation>
    </message>
    <message>
        <source>Keep your back against the chair</source>
        <translation>Lehnen Sie den Rücken an den Stuhl</translation>
    </message>
    <message>
        <source>Trunk cue</source>
        <translation>Hinweis zum Rumpf</translation>
    </message>
    <message>
        <source>Trunk</source>
        <translation>Rumpf</translation>
    </message>
    <message>
        <source>Repetitions with compensation</source>
        <translation>Wiederholungen mit Kompensation</translation>
    </message>
    <message>
        <source>Trunk limit %1: %2 of %3 repetitions with compensation</source>
        <translation>Rumpfgrenze %1: %2 von %3 Wiederholungen mit Kompensation</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::RecordingTarget</name>
    <message>
        <source>a recording with this name exists; choose another name</source>
        <translation>eine Aufnahme mit diesem Namen gibt es schon; wählen Sie einen anderen Namen</translation>
    </message>
    <message>
        <source>the records of patient %1</source>
        <translation>die Akte von Patient %1</translation>
    </message>
    <message>
        <source>cannot record into the records: %1</source>
        <translation>Aufnahme in die Akten nicht möglich: %1</translation>
    </message>
    <message>
        <source>%L1 rows recorded in %2</source>
        <translation>%L1 Zeilen in %2 aufgenommen</translation>
    </message>
    <message>
        <source>%L1 rows recorded in %2; some rows could not be written</source>
        <translation>%L1 Zeilen in %2 aufgenommen; einige Zeilen konnten nicht geschrieben werden</translation>
    </message>
    <message>
        <source>session %1: %L2 rows recorded, but it could not be closed: %3</source>
        <translation>Sitzung %1: %L2 Zeilen aufgenommen, aber sie konnte nicht abgeschlossen werden: %3</translation>
    </message>
    <message>
        <source>session %1 saved in the records: %L2 rows</source>
        <translation>Sitzung %1 in den Akten gespeichert: %L2 Zeilen</translation>
    </message>
    <message>
        <source>cannot create the folder %1 (%2): choose a folder you may write to</source>
        <translation>der Ordner %1 kann nicht angelegt werden (%2): wählen Sie einen Ordner, in den Sie schreiben dürfen</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::SensorCalibrationPage</name>
    <message>
        <source>upper-arm gyroscope</source>
        <translation>Oberarm-Gyroskop</translation>
    </message>
    <message>
        <source>upper-arm accelerometer</source>
        <translation>Oberarm-Beschleunigungssensor</translation>
    </message>
    <message>
        <source>forearm gyroscope</source>
        <translation>Unterarm-Gyroskop</translation>
    </message>
    <message>
        <source>forearm accelerometer</source>
        <translation>Unterarm-Beschleunigungssensor</translation>
    </message>
    <message>
        <source>optical positions</source>
        <translation>optische Positionen</translation>
    </message>
    <message>
        <source>Sensor calibration</source>
        <translation>Sensorkalibrierung</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Anweisung</translation>
    </message>
    <message>
        <source>Time left in this step</source>
        <translation>Verbleibende Zeit in diesem Schritt</translation>
    </message>
    <message>
        <source>Protocol progress</source>
        <translation>Fortschritt des Protokolls</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>C&amp;ancel</source>
        <translation>A&amp;bbrechen</translation>
    </message>
    <message>
        <source>Calibration verdict</source>
        <translation>Ergebnis der Kalibrierung</translation>
    </message>
    <message>
        <source>Calibration details</source>
        <translation>Einzelheiten der Kalibrierung</translation>
    </message>
    <message>
        <source>The devices could not start: %1</source>
        <translation>Die Geräte konnten nicht starten: %1</translation>
    </message>
    <message>
        <source>The protocol could not be recorded: %1</source>
        <translation>Das Protokoll konnte nicht aufgenommen werden: %1</translation>
    </message>
    <message>
        <source>no data arrived</source>
        <translation>es kamen keine Daten an</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>Starting the sensors…</source>
        <translation>Sensoren werden gestartet …</translation>
    </message>
    <message>
        <source>Recorded</source>
        <translation>Aufgenommen</translation>
    </message>
    <message>
        <source>The patient can relax.</source>
        <translation>Der Patient kann sich entspannen.</translation>
    </message>
    <message>
        <source>Calibrating…</source>
        <translation>Kalibrierung läuft …</translation>
    </message>
    <message>
        <source>Fitting the sensors&apos; mounting to the recording (this takes a few seconds).</source>
        <translation>Die Lage der Sensoren wird an die Aufnahme angepasst (das dauert einige Sekunden).</translation>
    </message>
    <message>
        <source>The calibration failed: %1. Redo the protocol.</source>
        <translation>Die Kalibrierung ist fehlgeschlagen: %1. Wiederholen Sie das Protokoll.</translation>
    </message>
    <message>
        <source>Upper-arm strap angle %1 deg, forearm strap angle %2 deg; residuals (noise levels): upper gyro %3, upper acc %4, forearm gyro %5, forearm acc %6, optical %7; %8 iterations.</source>
        <translation>Gurtwinkel Oberarm %1°, Gurtwinkel Unterarm %2°; Residuen (Rauschniveaus): Gyro oben %3, Beschl. oben %4, Gyro Unterarm %5, Beschl. Unterarm %6, optisch %7; %8 Iterationen.</translation>
    </message>
    <message>
        <source>Calibration done</source>
        <translation>Kalibrierung abgeschlossen</translation>
    </message>
    <message>
        <source>Cancelled. Press Start to begin the protocol again.</source>
        <translation>Abgebrochen. Auf „Starten“ drücken, um das Protokoll neu zu beginnen.</translation>
    </message>
    <message>
        <source>The fit did not settle. Check that both sensors are strapped tight, then redo the protocol.</source>
        <translation>Die Anpassung kam nicht zur Ruhe. Prüfen Sie, ob beide Sensoren fest sitzen, und wiederholen Sie das Protokoll.</translation>
    </message>
    <message>
        <source>The movements do not fit the arm model well (%1 off by %2 noise levels). Check the straps and the start pose, then redo the protocol.</source>
        <translation>Die Bewegungen passen schlecht zum Armmodell (%1 weicht um %2 Rauschniveaus ab). Prüfen Sie die Gurte und die Ausgangsstellung und wiederholen Sie das Protokoll.</translation>
    </message>
    <message>
        <source>Usable, not perfect (worst: %1 at %2 noise levels).</source>
        <translation>Brauchbar, nicht perfekt (am schlechtesten: %1 mit %2 Rauschniveaus).</translation>
    </message>
    <message>
        <source>Redo the protocol for a better one.</source>
        <translation>Wiederholen Sie das Protokoll für eine bessere.</translation>
    </message>
    <message>
        <source>Good: the data fit the arm model to the sensors&apos; noise level (worst: %1 at %2).</source>
        <translation>Gut: Die Daten passen bis auf das Rauschen der Sensoren zum Armmodell (am schlechtesten: %1 mit %2).</translation>
    </message>
    <message numerus="yes">
        <source>Hold still: %n s</source>
        <translation>
            <numerusform>Ruhig halten: %n s</numerusform>
            <numerusform>Ruhig halten: %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Move: %n s</source>
        <translation>
            <numerusform>Bewegen: %n s</numerusform>
            <numerusform>Bewegen: %n s</numerusform>
        </translation>
    </message>
    <message>
        <source>The patient sits upright with both sensors strapped on. Press Start, then follow the instructions on the screen for about a minute.</source>
        <translation>Der Patient sitzt aufrecht, beide Sensoren sind angelegt. Auf „Starten“ drücken und dann etwa eine Minute lang den Anweisungen auf dem Bildschirm folgen.</translation>
    </message>
    <message>
        <source>Done: the calibration is good.</source>
        <translation>Fertig: die Kalibrierung ist gut.</translation>
    </message>
    <message>
        <source>Done: the calibration can be used. If you have a minute, press Redo for a better one.</source>
        <translation>Fertig: die Kalibrierung ist brauchbar. Wenn Sie eine Minute Zeit haben, drücken Sie Wiederholen für eine bessere.</translation>
    </message>
    <message>
        <source>That did not work this time. Check that both straps are tight, then press Redo and follow the screen again, or go on without it.</source>
        <translation>Das hat diesmal nicht geklappt. Prüfen Sie, ob beide Bänder fest sitzen, drücken Sie dann Wiederholen und folgen Sie wieder dem Bildschirm, oder machen Sie ohne sie weiter.</translation>
    </message>
    <message>
        <source>You can relax.</source>
        <translation>Sie können sich entspannen.</translation>
    </message>
    <message>
        <source>You can relax. ArmTrack is working this out; it takes a few seconds.</source>
        <translation>Sie können sich entspannen. ArmTrack rechnet das jetzt aus; das dauert einige Sekunden.</translation>
    </message>
    <message>
        <source>Chest (sternum) sensor: its tilt is taken from the upright start pose; its heading about the vertical is kept as assumed.</source>
        <translation>Brustbeinsensor: seine Neigung wird aus der aufrechten Ausgangshaltung bestimmt; seine Ausrichtung um die Senkrechte bleibt wie angenommen.</translation>
    </message>
    <message>
        <source>The fit did not settle. Check that all three sensors are strapped tight, then redo the protocol.</source>
        <translation>Die Anpassung kam nicht zur Ruhe. Prüfen Sie, ob alle drei Sensoren fest sitzen, und wiederholen Sie das Protokoll.</translation>
    </message>
    <message>
        <source>The patient sits upright with all three sensors (upper arm, forearm and chest) strapped on. Press Start, then follow the instructions on the screen for about a minute.</source>
        <translation>Der Patient sitzt aufrecht, alle drei Sensoren (Oberarm, Unterarm und Brust) sind angelegt. Auf „Starten“ drücken und dann etwa eine Minute lang den Anweisungen auf dem Bildschirm folgen.</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::SessionController</name>
    <message>
        <source>a session is already running; stop it first</source>
        <translation>es läuft bereits eine Sitzung; beenden Sie sie zuerst</translation>
    </message>
    <message>
        <source>no device chosen: choose at least one device</source>
        <translation>kein Gerät gewählt: wählen Sie mindestens ein Gerät</translation>
    </message>
    <message>
        <source>no device plugin &quot;%1&quot;; found: %2. Check the plugin folders in the settings.</source>
        <translation>kein Geräte-Plugin „%1“; gefunden: %2. Prüfen Sie die Plugin-Ordner in den Einstellungen.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>the session could not start: %1</source>
        <translation>die Sitzung konnte nicht starten: %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::AppController</name>
    <message>
        <source>Preparing the demo</source>
        <translation>Demo wird vorbereitet</translation>
    </message>
    <message>
        <source>Making demo records in %1: three patients, two protocols and six weeks of sessions, simulated and analysed the way real ones are. This takes a few seconds.</source>
        <translation>Demo-Akten werden in %1 angelegt: drei Patienten, zwei Protokolle und sechs Wochen Sitzungen, simuliert und ausgewertet wie echte. Das dauert einige Sekunden.</translation>
    </message>
    <message>
        <source>Signing in as the demo therapist...</source>
        <translation>Anmeldung als Demo-Therapeut ...</translation>
    </message>
    <message>
        <source>%1 (%2, demo)</source>
        <translation>%1 (%2, Demo)</translation>
    </message>
    <message>
        <source>Demo records: accounts &quot;%1&quot; and &quot;%2&quot;, password &quot;%3&quot;.</source>
        <translation>Demo-Akten: Konten „%1“ und „%2“, Passwort „%3“.</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <source>Settings saved.</source>
        <translation>Einstellungen gespeichert.</translation>
    </message>
    <message>
        <source>The new records location is used at the next sign-in.</source>
        <translation>Der neue Speicherort der Akten gilt ab der nächsten Anmeldung.</translation>
    </message>
    <message>
        <source>Opening the records</source>
        <translation>Akten werden geöffnet</translation>
    </message>
    <message>
        <source>Opening %1...</source>
        <translation>%1 wird geöffnet ...</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Analysing the session</source>
        <translation>Sitzung wird ausgewertet</translation>
    </message>
    <message>
        <source>Estimating the joint angles of session %1 again from its recording and computing its metrics...</source>
        <translation>Die Gelenkwinkel von Sitzung %1 werden aus ihrer Aufnahme neu berechnet, dazu ihre Kennwerte ...</translation>
    </message>
    <message>
        <source>Session %1 is saved, but it could not be analysed: %2
You can re-estimate it from its review.</source>
        <translation>Sitzung %1 ist gespeichert, konnte aber nicht ausgewertet werden: %2
Sie können sie in ihrer Auswertung neu berechnen.</translation>
    </message>
    <message>
        <source>&amp;Review session</source>
        <translation>Sitzung &amp;auswerten</translation>
    </message>
    <message>
        <source>&amp;Back to the patient</source>
        <translation>&amp;Zurück zum Patienten</translation>
    </message>
    <message>
        <source>&amp;Skip the analysis</source>
        <translation>Auswertung ü&amp;berspringen</translation>
    </message>
    <message>
        <source>Back the file up, then bring it up to date with: armtrack-cli db migrate</source>
        <translation>Sichern Sie die Datei und bringen Sie sie dann auf den neuesten Stand mit: armtrack-cli db migrate</translation>
    </message>
    <message>
        <source>Install the newer ArmTrack that wrote it.</source>
        <translation>Installieren Sie die neuere ArmTrack-Version, die sie geschrieben hat.</translation>
    </message>
    <message>
        <source>The file was left untouched. Restore it from a backup, or choose another database in the settings.</source>
        <translation>Die Datei wurde nicht verändert. Stellen Sie sie aus einer Sicherung wieder her oder wählen Sie in den Einstellungen eine andere Datenbank.</translation>
    </message>
    <message>
        <source>Check the location in the settings (or --db) and that you may read and write it, then try again.</source>
        <translation>Prüfen Sie den Speicherort in den Einstellungen (oder --db) und ob Sie dort lesen und schreiben dürfen, dann erneut versuchen.</translation>
    </message>
    <message>
        <source>The records cannot be opened</source>
        <translation>Die Akten können nicht geöffnet werden</translation>
    </message>
    <message>
        <source>&amp;Try again</source>
        <translation>&amp;Erneut versuchen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>administrator</source>
        <translation>Administrator</translation>
    </message>
    <message>
        <source>therapist</source>
        <translation>Therapeut</translation>
    </message>
    <message>
        <source>home account</source>
        <translation>Heimkonto</translation>
    </message>
    <message>
        <source>Signing in as the demo patient at home...</source>
        <translation>Anmeldung als Demo-Patientin zu Hause ...</translation>
    </message>
    <message numerus="yes">
        <source>%n earlier session(s) analysed</source>
        <translation>
            <numerusform>%n frühere Sitzung ausgewertet</numerusform>
            <numerusform>%n frühere Sitzungen ausgewertet</numerusform>
        </translation>
    </message>
    <message>
        <source>Earlier sessions could not be analysed now: %1</source>
        <translation>Frühere Sitzungen konnten jetzt nicht ausgewertet werden: %1</translation>
    </message>
    <message>
        <source>Session %1 was too short to analyse: %2 s were recorded, and at least %3 s are needed. It is kept, marked as too short.
To measure the movement, start a new session, press Record, let the patient do the movement, then press Stop.</source>
        <translation>Sitzung %1 war zu kurz für eine Auswertung: %2 s wurden aufgezeichnet, mindestens %3 s sind nötig. Sie bleibt gespeichert und ist als zu kurz markiert.
Um die Bewegung zu messen, beginnen Sie eine neue Sitzung, drücken Sie Aufnehmen, lassen Sie den Patienten die Bewegung machen und drücken Sie dann Beenden.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::BirthDateField</name>
    <message>
        <source>not given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source>Birth date</source>
        <translation>Geburtsdatum</translation>
    </message>
    <message>
        <source>Type the date as %1 or %2; leave it empty when not given. Up and Down change it by a day, Alt+Down opens a calendar.</source>
        <translation>Geben Sie das Datum als %1 oder %2 ein; leer lassen, wenn nicht angegeben. Pfeil hoch und runter ändern es um einen Tag, Alt+Pfeil runter öffnet einen Kalender.</translation>
    </message>
    <message>
        <source>Choose the birth date from a calendar</source>
        <translation>Geburtsdatum aus einem Kalender wählen</translation>
    </message>
    <message>
        <source>a birth date from %1 up to today, %2</source>
        <translation>ein Geburtsdatum vom %1 bis heute, %2</translation>
    </message>
    <message>
        <source>Born: &quot;%1&quot; is not a date. Type %2 as %3 or %4, or leave the field empty when the birth date is not given.</source>
        <translation>Geboren: „%1“ ist kein Datum. Geben Sie %2 als %3 oder %4 ein, oder lassen Sie das Feld leer, wenn das Geburtsdatum nicht angegeben ist.</translation>
    </message>
    <message>
        <source>Born: %1 is not possible. Type %2.</source>
        <translation>Geboren: %1 ist nicht möglich. Geben Sie %2 ein.</translation>
    </message>
    <message>
        <source>Calendar</source>
        <translation>Kalender</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::CloseWhileRecording</name>
    <message>
        <source>A recording is under way</source>
        <translation>Eine Aufnahme läuft</translation>
    </message>
    <message>
        <source>Stop the recording and save the session before closing?</source>
        <translation>Die Aufnahme beenden und die Sitzung vor dem Schließen speichern?</translation>
    </message>
    <message>
        <source>Stop and save ends the session as the Stop button does and closes ArmTrack; the session is analysed when ArmTrack next starts. Keep recording goes back to the session.</source>
        <translation>Stoppen und speichern beendet die Sitzung wie die Taste Beenden und schließt ArmTrack; die Sitzung wird beim nächsten Start von ArmTrack ausgewertet. Weiter aufnehmen kehrt zur Sitzung zurück.</translation>
    </message>
    <message>
        <source>&amp;Stop and save</source>
        <translation>&amp;Stoppen und speichern</translation>
    </message>
    <message>
        <source>&amp;Keep recording</source>
        <translation>&amp;Weiter aufnehmen</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::DeviceTableModel</name>
    <message>
        <source>Device %1</source>
        <translation>Gerät %1</translation>
    </message>
    <message>
        <source>device %1</source>
        <translation>Gerät %1</translation>
    </message>
    <message>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <source>enrolled</source>
        <translation>angemeldet</translation>
    </message>
    <message>
        <source>revoked %1</source>
        <translation>gesperrt %1</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Enrolled</source>
        <translation>Angemeldet</translation>
    </message>
    <message>
        <source>Last sync</source>
        <translation>Letzte Synchronisierung</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::FirstRunScreen</name>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Durchsuchen ...</translation>
    </message>
    <message>
        <source>&amp;Create and sign in</source>
        <translation>&amp;Anlegen und anmelden</translation>
    </message>
    <message>
        <source>First start</source>
        <translation>Erster Start</translation>
    </message>
    <message>
        <source>Welcome to ArmTrack</source>
        <translation>Willkommen bei ArmTrack</translation>
    </message>
    <message>
        <source>Where the data lives</source>
        <translation>Speicherort der Daten</translation>
    </message>
    <message>
        <source>The database given on the command line: %1</source>
        <translation>Die auf der Befehlszeile angegebene Datenbank: %1</translation>
    </message>
    <message>
        <source>Data folder</source>
        <translation>Datenordner</translation>
    </message>
    <message>
        <source>Choose the data folder</source>
        <translation>Datenordner wählen</translation>
    </message>
    <message>
        <source>Administrator account</source>
        <translation>Administratorkonto</translation>
    </message>
    <message>
        <source>Administrator name</source>
        <translation>Name des Administrators</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message numerus="yes">
        <source>at least %n characters</source>
        <translation>
            <numerusform>mindestens %n Zeichen</numerusform>
            <numerusform>mindestens %n Zeichen</numerusform>
        </translation>
    </message>
    <message>
        <source>Password again</source>
        <translation>Passwort wiederholen</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Passwort:</translation>
    </message>
    <message>
        <source>Password &amp;again:</source>
        <translation>Passwort &amp;wiederholen:</translation>
    </message>
    <message>
        <source>Choose a folder.</source>
        <translation>Wählen Sie einen Ordner.</translation>
    </message>
    <message>
        <source>The records will be kept in %1.</source>
        <translation>Die Akten werden in %1 gespeichert.</translation>
    </message>
    <message>
        <source>Where ArmTrack keeps its data</source>
        <translation>Wo ArmTrack seine Daten speichert</translation>
    </message>
    <message>
        <source>Choose the folder where ArmTrack keeps its data.</source>
        <translation>Wählen Sie den Ordner, in dem ArmTrack seine Daten speichert.</translation>
    </message>
    <message>
        <source>Give the data folder as a full path, e.g. %1.</source>
        <translation>Geben Sie den Datenordner als vollständigen Pfad an, z. B. %1.</translation>
    </message>
    <message>
        <source>Give the administrator a name.</source>
        <translation>Geben Sie dem Administrator einen Namen.</translation>
    </message>
    <message numerus="yes">
        <source>The password needs at least %n characters.</source>
        <translation>
            <numerusform>Das Passwort braucht mindestens %n Zeichen.</numerusform>
            <numerusform>Das Passwort braucht mindestens %n Zeichen.</numerusform>
        </translation>
    </message>
    <message>
        <source>The two passwords differ. Type the same password twice.</source>
        <translation>Die beiden Passwörter unterscheiden sich. Geben Sie zweimal dasselbe Passwort ein.</translation>
    </message>
    <message>
        <source>Creating the records...</source>
        <translation>Akten werden angelegt ...</translation>
    </message>
    <message>
        <source>ArmTrack keeps its patients, sessions and recordings in one database. Choose where it lives and create the administrator account; the administrator then adds the therapists&apos; accounts, the protocols and the home programmes under ArmTrack &gt; Administration.</source>
        <translation>ArmTrack speichert Patienten, Sitzungen und Aufzeichnungen in einer Datenbank. Wählen Sie, wo sie liegt, und legen Sie das Administratorkonto an; der Administrator legt dann unter ArmTrack &gt; Verwaltung die Konten der Therapeuten, die Protokolle und die Heimprogramme an.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::HelpWindow</name>
    <message>
        <source>Choose where the records are kept and name the administrator; then press Create.</source>
        <translation>Wählen Sie, wo die Daten liegen, und benennen Sie den Administrator; dann Anlegen drücken.</translation>
    </message>
    <message>
        <source>Type your account name and password, then press Sign in.</source>
        <translation>Kontonamen und Passwort eingeben, dann Anmelden drücken.</translation>
    </message>
    <message>
        <source>Find a patient by name or code and open their page (Enter), or add a new patient (Ctrl+N).</source>
        <translation>Einen Patienten nach Name oder Code suchen und seine Seite öffnen (Eingabe), oder einen neuen Patienten anlegen (Strg+N).</translation>
    </message>
    <message>
        <source>See the patient&apos;s sessions and progress; start a new session (Ctrl+R) or open a session to review it (Enter).</source>
        <translation>Sitzungen und Verlauf des Patienten ansehen; eine neue Sitzung beginnen (Strg+R) oder eine Sitzung zur Auswertung öffnen (Eingabe).</translation>
    </message>
    <message>
        <source>Go through the steps: protocol and arm, the device check, the sensors&apos; calibration and the camera; Finish starts the session.</source>
        <translation>Die Schritte durchgehen: Protokoll und Arm, Prüfung der Geräte, Kalibrierung der Sensoren und die Kamera; Fertigstellen startet die Sitzung.</translation>
    </message>
    <message>
        <source>Watch the arm and the angles; press Record (Ctrl+R) to keep the movement and Stop (Ctrl+E) when the exercise is done.</source>
        <translation>Arm und Winkel beobachten; Aufnehmen (Strg+R) speichert die Bewegung, Beenden (Strg+E), wenn die Übung fertig ist.</translation>
    </message>
    <message>
        <source>Move through the session with the slider or by clicking a plot; compare, re-estimate or write a report.</source>
        <translation>Mit dem Schieberegler oder einem Klick in ein Diagramm durch die Sitzung gehen; vergleichen, neu schätzen oder einen Bericht schreiben.</translation>
    </message>
    <message>
        <source>The guide describes every screen; its contents are at the top.</source>
        <translation>Das Handbuch beschreibt jeden Bildschirm; sein Inhalt steht am Anfang.</translation>
    </message>
    <message>
        <source>ArmTrack user guide</source>
        <translation>ArmTrack-Benutzerhandbuch</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <source>What to do here</source>
        <translation>Was hier zu tun ist</translation>
    </message>
    <message>
        <source>The guide is not yet translated into your language; it is shown in English.</source>
        <translation>Das Handbuch ist noch nicht in Ihre Sprache übersetzt; es wird auf Englisch gezeigt.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::HomeDevicesBox</name>
    <message>
        <source>The code is copied.</source>
        <translation>Der Code ist kopiert.</translation>
    </message>
    <message>
        <source>Home devices</source>
        <translation>Heimgeräte</translation>
    </message>
    <message>
        <source>Home &amp;account:</source>
        <translation>Heim&amp;konto:</translation>
    </message>
    <message>
        <source>Home account</source>
        <translation>Heimkonto</translation>
    </message>
    <message>
        <source>Code va&amp;lid for:</source>
        <translation>Code gü&amp;ltig für:</translation>
    </message>
    <message>
        <source>Code valid for</source>
        <translation>Code gültig für</translation>
    </message>
    <message>
        <source>1 hour</source>
        <translation>1 Stunde</translation>
    </message>
    <message>
        <source>1 day</source>
        <translation>1 Tag</translation>
    </message>
    <message>
        <source>7 days</source>
        <translation>7 Tage</translation>
    </message>
    <message>
        <source>30 days</source>
        <translation>30 Tage</translation>
    </message>
    <message>
        <source>This patient has no home account yet. An administrator adds one (Administration, Accounts); then make an enrolment code here.</source>
        <translation>Dieser Patient hat noch kein Heimkonto. Ein Administrator legt eines an (Verwaltung, Konten); dann erstellen Sie hier einen Anmeldecode.</translation>
    </message>
    <message>
        <source>Make enrolment &amp;code</source>
        <translation>Anmelde&amp;code erstellen</translation>
    </message>
    <message>
        <source>A one-time code the patient types on their home computer to connect it to the clinic</source>
        <translation>Ein einmaliger Code, den der Patient auf seinem Computer zu Hause eingibt, um ihn mit der Praxis zu verbinden</translation>
    </message>
    <message>
        <source>Enrolment code</source>
        <translation>Anmeldecode</translation>
    </message>
    <message>
        <source>Cop&amp;y code</source>
        <translation>Code kop&amp;ieren</translation>
    </message>
    <message>
        <source>Enrolled &amp;devices:</source>
        <translation>Angemeldete &amp;Geräte:</translation>
    </message>
    <message>
        <source>Enrolled devices</source>
        <translation>Angemeldete Geräte</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>A&amp;ktualisieren</translation>
    </message>
    <message>
        <source>Read the devices again (a patient may have enrolled meanwhile)</source>
        <translation>Die Geräte neu lesen (ein Patient kann sich inzwischen angemeldet haben)</translation>
    </message>
    <message>
        <source>Re&amp;voke device...</source>
        <translation>Gerät &amp;sperren ...</translation>
    </message>
    <message>
        <source>Only therapists and administrators may make enrolment codes and see or revoke home devices. Ask one of them.</source>
        <translation>Nur Therapeuten und Administratoren dürfen Anmeldecodes erstellen und Heimgeräte sehen oder sperren. Fragen Sie eine dieser Personen.</translation>
    </message>
    <message>
        <source>%1 (disabled)</source>
        <translation>%1 (deaktiviert)</translation>
    </message>
    <message>
        <source>Making the code...</source>
        <translation>Code wird erstellt ...</translation>
    </message>
    <message>
        <source>For %1, once, until %2. The patient types it when their home computer asks to connect to the clinic.</source>
        <translation>Für %1, einmalig, bis %2. Der Patient gibt ihn ein, wenn sein Computer zu Hause nach der Verbindung mit der Praxis fragt.</translation>
    </message>
    <message>
        <source>For %1, once, until %2. The patient types it, with the server address %3, when their home computer asks to connect to the clinic.</source>
        <translation>Für %1, einmalig, bis %2. Der Patient gibt ihn mit der Serveradresse %3 ein, wenn sein Computer zu Hause nach der Verbindung mit der Praxis fragt.</translation>
    </message>
    <message>
        <source>Revoke device</source>
        <translation>Gerät sperren</translation>
    </message>
    <message>
        <source>Revoke the device &quot;%1&quot; of %2? It can no longer send sessions or fetch the programme; to use it again the patient enrols it with a new code. Sessions it sent stay.</source>
        <translation>Das Gerät „%1“ von %2 sperren? Es kann dann keine Sitzungen mehr senden und das Programm nicht mehr abrufen; um es wieder zu nutzen, meldet der Patient es mit einem neuen Code an. Bereits gesendete Sitzungen bleiben.</translation>
    </message>
    <message>
        <source>Re&amp;voke</source>
        <translation>&amp;Sperren</translation>
    </message>
    <message>
        <source>The device &quot;%1&quot; is revoked.</source>
        <translation>Das Gerät „%1“ ist gesperrt.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::JobProgress</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stopping...</source>
        <translation>Wird angehalten ...</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MainWindow</name>
    <message>
        <source>Signed-in account</source>
        <translation>Angemeldetes Konto</translation>
    </message>
    <message>
        <source>&amp;ArmTrack</source>
        <translation>&amp;ArmTrack</translation>
    </message>
    <message>
        <source>&amp;Patients</source>
        <translation>&amp;Patienten</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation>&amp;Einstellungen ...</translation>
    </message>
    <message>
        <source>Ctrl+,</source>
        <translation>Ctrl+,</translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation>&amp;Abmelden</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;About ArmTrack</source>
        <translation>Ü&amp;ber ArmTrack</translation>
    </message>
    <message>
        <source>About ArmTrack</source>
        <translation>Über ArmTrack</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;ArmTrack %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Measures the shoulder&apos;s and elbow&apos;s joint angles from two wearable IMUs and a Kinect or webcam, for upper-limb rehabilitation.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;ArmTrack %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Misst die Gelenkwinkel von Schulter und Ellenbogen mit zwei am Körper getragenen IMUs und einer Kinect oder Webcam, für die Rehabilitation der oberen Extremität.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Signed in as %1</source>
        <translation>Angemeldet als %1</translation>
    </message>
    <message>
        <source>ArmTrack</source>
        <translation>ArmTrack</translation>
    </message>
    <message>
        <source>%1 - ArmTrack</source>
        <translation>%1 – ArmTrack</translation>
    </message>
    <message>
        <source>A&amp;dministration...</source>
        <translation>&amp;Verwaltung...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+D</source>
        <translation>Ctrl+Shift+D</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MessageLine</name>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MessageScreen</name>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>Progress</source>
        <translation>Fortschritt</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::NewSessionScreen</name>
    <message>
        <source>New session</source>
        <translation>Neue Sitzung</translation>
    </message>
    <message>
        <source>&amp;Start the live session</source>
        <translation>Live-Sitzung &amp;starten</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <source>Choose the sensors and their options, then check the connection: every stream should turn green and the angles move with the arm.</source>
        <translation>Sensoren und ihre Optionen wählen, dann die Verbindung prüfen: Jeder Datenstrom sollte grün werden und die Winkel sich mit dem Arm bewegen.</translation>
    </message>
    <message>
        <source>Sensor calibration</source>
        <translation>Sensorkalibrierung</translation>
    </message>
    <message>
        <source>The patient holds and makes the movements shown; ArmTrack then works out how the sensors sit on the arm. About a minute.</source>
        <translation>Der Patient hält die gezeigten Stellungen und macht die gezeigten Bewegungen; ArmTrack ermittelt daraus, wie die Sensoren am Arm sitzen. Etwa eine Minute.</translation>
    </message>
    <message>
        <source>Skip the calibration (the measured segment lengths are used)</source>
        <translation>Kalibrierung überspringen (die gemessenen Segmentlängen werden verwendet)</translation>
    </message>
    <message>
        <source>Camera calibration</source>
        <translation>Kamerakalibrierung</translation>
    </message>
    <message>
        <source>Hold the printed chessboard in front of the webcam in different places and angles until the grid is covered.</source>
        <translation>Das gedruckte Schachbrett an verschiedenen Stellen und in verschiedenen Winkeln vor die Webcam halten, bis das Raster abgedeckt ist.</translation>
    </message>
    <message>
        <source>Skip the camera calibration (use the camera&apos;s stored model)</source>
        <translation>Kamerakalibrierung überspringen (das gespeicherte Kameramodell verwenden)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::OutputsPanel</name>
    <message>
        <source>&amp;PDF report...</source>
        <translation>&amp;PDF-Bericht ...</translation>
    </message>
    <message>
        <source>The session report: details, metrics, plots, repetitions</source>
        <translation>Der Sitzungsbericht: Angaben, Kennwerte, Diagramme, Wiederholungen</translation>
    </message>
    <message>
        <source>C&amp;SV...</source>
        <translation>C&amp;SV ...</translation>
    </message>
    <message>
        <source>Angles (deg) with their uncertainty, and a metrics table</source>
        <translation>Winkel (°) mit ihrer Unsicherheit und eine Tabelle der Kennwerte</translation>
    </message>
    <message>
        <source>Open&amp;Sim .mot...</source>
        <translation>Open&amp;Sim .mot ...</translation>
    </message>
    <message>
        <source>The clinical angles as an OpenSim motion file</source>
        <translation>Die klinischen Winkel als OpenSim-Bewegungsdatei</translation>
    </message>
    <message>
        <source>&amp;BIDS...</source>
        <translation>&amp;BIDS ...</translation>
    </message>
    <message>
        <source>A BIDS motion data set: IMUs, optical data and angles</source>
        <translation>Ein BIDS-Bewegungsdatensatz: IMUs, optische Daten und Winkel</translation>
    </message>
    <message>
        <source>Rec&amp;ording...</source>
        <translation>Auf&amp;nahme ...</translation>
    </message>
    <message>
        <source>The raw recording in the open format, bit for bit</source>
        <translation>Die Rohaufnahme im offenen Format, Bit für Bit</translation>
    </message>
    <message>
        <source>Last output</source>
        <translation>Letzte Ausgabe</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientDialog</name>
    <message>
        <source>New patient</source>
        <translation>Neuer Patient</translation>
    </message>
    <message>
        <source>Edit patient %1</source>
        <translation>Patient %1 bearbeiten</translation>
    </message>
    <message>
        <source>Upper arm length</source>
        <translation>Oberarmlänge</translation>
    </message>
    <message>
        <source>Forearm length</source>
        <translation>Unterarmlänge</translation>
    </message>
    <message>
        <source>Upper-arm IMU distance from the shoulder</source>
        <translation>Abstand der Oberarm-IMU von der Schulter</translation>
    </message>
    <message>
        <source>Forearm IMU distance from the elbow</source>
        <translation>Abstand der Unterarm-IMU vom Ellenbogen</translation>
    </message>
    <message>
        <source>Patient code</source>
        <translation>Patientenkennung</translation>
    </message>
    <message>
        <source>e.g. P001</source>
        <translation>z. B. P001</translation>
    </message>
    <message>
        <source>Patient name</source>
        <translation>Name des Patienten</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source>Sex</source>
        <translation>Geschlecht</translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation>Betroffene Seite</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnose</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patient</translation>
    </message>
    <message>
        <source>&amp;Code:</source>
        <translation>&amp;Kennung:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Born:</source>
        <translation>&amp;Geboren:</translation>
    </message>
    <message>
        <source>&amp;Sex:</source>
        <translation>Ge&amp;schlecht:</translation>
    </message>
    <message>
        <source>Affected &amp;side:</source>
        <translation>Betroffene &amp;Seite:</translation>
    </message>
    <message>
        <source>&amp;Diagnosis:</source>
        <translation>&amp;Diagnose:</translation>
    </message>
    <message>
        <source>Measured segment lengths</source>
        <translation>Gemessene Segmentlängen</translation>
    </message>
    <message>
        <source>&amp;Upper arm (shoulder to elbow):</source>
        <translation>&amp;Oberarm (Schulter bis Ellenbogen):</translation>
    </message>
    <message>
        <source>&amp;Forearm (elbow to wrist):</source>
        <translation>&amp;Unterarm (Ellenbogen bis Handgelenk):</translation>
    </message>
    <message>
        <source>Upper-arm IMU from the shoulder:</source>
        <translation>Oberarm-IMU ab der Schulter:</translation>
    </message>
    <message>
        <source>Forearm IMU from the elbow:</source>
        <translation>Unterarm-IMU ab dem Ellenbogen:</translation>
    </message>
    <message>
        <source>N&amp;otes</source>
        <translation>N&amp;otizen</translation>
    </message>
    <message>
        <source>Saving...</source>
        <translation>Wird gespeichert ...</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientListScreen</name>
    <message>
        <source>&amp;Open</source>
        <translation>Ö&amp;ffnen</translation>
    </message>
    <message>
        <source>&amp;New patient...</source>
        <translation>&amp;Neuer Patient ...</translation>
    </message>
    <message>
        <source>&amp;Edit...</source>
        <translation>&amp;Bearbeiten ...</translation>
    </message>
    <message>
        <source>Patients</source>
        <translation>Patienten</translation>
    </message>
    <message>
        <source>&amp;Search:</source>
        <translation>&amp;Suchen:</translation>
    </message>
    <message>
        <source>code, name, diagnosis...</source>
        <translation>Kennung, Name, Diagnose ...</translation>
    </message>
    <message>
        <source>Search patients</source>
        <translation>Patienten suchen</translation>
    </message>
    <message>
        <source>Patient list</source>
        <translation>Patientenliste</translation>
    </message>
    <message>
        <source>Add a patient (%1)</source>
        <translation>Einen Patienten hinzufügen (%1)</translation>
    </message>
    <message>
        <source>Loading the patients...</source>
        <translation>Patienten werden geladen ...</translation>
    </message>
    <message>
        <source>No patients yet. Add the first with &quot;New patient&quot;.</source>
        <translation>Noch keine Patienten. Legen Sie den ersten mit „Neuer Patient“ an.</translation>
    </message>
    <message>
        <source>No patients.</source>
        <translation>Keine Patienten.</translation>
    </message>
    <message>
        <source>The patients could not be read: %1</source>
        <translation>Die Patienten konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>A patient with the code %1 exists already. Choose another code, or cancel and open that patient from the list.</source>
        <translation>Einen Patienten mit der Kennung %1 gibt es schon. Wählen Sie eine andere Kennung oder brechen Sie ab und öffnen Sie diesen Patienten aus der Liste.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientRecords</name>
    <message>
        <source>Give the patient a code, e.g. P001: it names the patient in files and exports.</source>
        <translation>Geben Sie dem Patienten eine Kennung, z. B. P001: Sie benennt den Patienten in Dateien und Exporten.</translation>
    </message>
    <message>
        <source>The code may hold letters, digits, &apos;-&apos; and &apos;_&apos; (at most 32, starting with a letter or digit): &quot;%1&quot; does not.</source>
        <translation>Die Kennung darf Buchstaben, Ziffern, „-“ und „_“ enthalten (höchstens 32, beginnend mit einem Buchstaben oder einer Ziffer): „%1“ erfüllt das nicht.</translation>
    </message>
    <message>
        <source>Give the patient&apos;s name.</source>
        <translation>Geben Sie den Namen des Patienten an.</translation>
    </message>
    <message>
        <source>The birth date is not a date.</source>
        <translation>Das Geburtsdatum ist kein Datum.</translation>
    </message>
    <message>
        <source>The birth date lies in the future.</source>
        <translation>Das Geburtsdatum liegt in der Zukunft.</translation>
    </message>
    <message>
        <source>The birth date is before 1900.</source>
        <translation>Das Geburtsdatum liegt vor 1900.</translation>
    </message>
    <message>
        <source>upper arm length</source>
        <translation>Oberarmlänge</translation>
    </message>
    <message>
        <source>forearm length</source>
        <translation>Unterarmlänge</translation>
    </message>
    <message>
        <source>upper-arm IMU distance</source>
        <translation>Abstand der Oberarm-IMU</translation>
    </message>
    <message>
        <source>forearm IMU distance</source>
        <translation>Abstand der Unterarm-IMU</translation>
    </message>
    <message>
        <source>The upper-arm IMU sits farther from the shoulder than the elbow is: check both measurements.</source>
        <translation>Die Oberarm-IMU sitzt weiter von der Schulter entfernt als der Ellenbogen: prüfen Sie beide Messungen.</translation>
    </message>
    <message>
        <source>The forearm IMU sits farther from the elbow than the wrist is: check both measurements.</source>
        <translation>Die Unterarm-IMU sitzt weiter vom Ellenbogen entfernt als das Handgelenk: prüfen Sie beide Messungen.</translation>
    </message>
    <message>
        <source>The %1 of %L2 cm is outside %L3-%L4 cm: check the measurement.</source>
        <translation>%1: %L2 cm liegt außerhalb von %L3–%L4 cm; prüfen Sie die Messung.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientScreen</name>
    <message>
        <source>&amp;New session...</source>
        <translation>&amp;Neue Sitzung ...</translation>
    </message>
    <message>
        <source>&amp;Review session</source>
        <translation>Sitzung &amp;auswerten</translation>
    </message>
    <message>
        <source>&amp;Progress report (PDF)...</source>
        <translation>&amp;Verlaufsbericht (PDF) ...</translation>
    </message>
    <message>
        <source>&amp;Edit patient...</source>
        <translation>Patient &amp;bearbeiten ...</translation>
    </message>
    <message>
        <source>&amp;Back to patients</source>
        <translation>&amp;Zurück zu den Patienten</translation>
    </message>
    <message>
        <source>Patient %1</source>
        <translation>Patient %1</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Angaben</translation>
    </message>
    <message>
        <source>Code:</source>
        <translation>Kennung:</translation>
    </message>
    <message>
        <source>Born:</source>
        <translation>Geboren:</translation>
    </message>
    <message>
        <source>Sex:</source>
        <translation>Geschlecht:</translation>
    </message>
    <message>
        <source>Affected side:</source>
        <translation>Betroffene Seite:</translation>
    </message>
    <message>
        <source>Diagnosis:</source>
        <translation>Diagnose:</translation>
    </message>
    <message>
        <source>Notes:</source>
        <translation>Notizen:</translation>
    </message>
    <message>
        <source>Measured segment lengths</source>
        <translation>Gemessene Segmentlängen</translation>
    </message>
    <message>
        <source>Upper arm:</source>
        <translation>Oberarm:</translation>
    </message>
    <message>
        <source>Forearm:</source>
        <translation>Unterarm:</translation>
    </message>
    <message>
        <source>Upper-arm IMU:</source>
        <translation>Oberarm-IMU:</translation>
    </message>
    <message>
        <source>Forearm IMU:</source>
        <translation>Unterarm-IMU:</translation>
    </message>
    <message>
        <source>Home programme</source>
        <translation>Heimprogramm</translation>
    </message>
    <message>
        <source>Progress</source>
        <translation>Fortschritt</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sitzungen</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>Loading...</source>
        <translation>Wird geladen ...</translation>
    </message>
    <message>
        <source>This patient could not be read: %1</source>
        <translation>Dieser Patient konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message numerus="yes">
        <source>%n stored length(s) could not be read.</source>
        <translation>
            <numerusform>%n gespeicherte Länge konnte nicht gelesen werden.</numerusform>
            <numerusform>%n gespeicherte Längen konnten nicht gelesen werden.</numerusform>
        </translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Per week</source>
        <translation>Pro Woche</translation>
    </message>
    <message>
        <source>Save the progress report</source>
        <translation>Verlaufsbericht speichern</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
    <message>
        <source>Writing the progress report...</source>
        <translation>Verlaufsbericht wird geschrieben ...</translation>
    </message>
    <message numerus="yes">
        <source>Progress report written: %1 (%n page(s)).</source>
        <translation>
            <numerusform>Verlaufsbericht geschrieben: %1 (%n Seite).</numerusform>
            <numerusform>Verlaufsbericht geschrieben: %1 (%n Seiten).</numerusform>
        </translation>
    </message>
    <message>
        <source>The progress report could not be written: %1. Choose another folder or file name and try again.</source>
        <translation>Der Verlaufsbericht konnte nicht geschrieben werden: %1. Wählen Sie einen anderen Ordner oder Dateinamen und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>%L1 cm</source>
        <translation>%L1 cm</translation>
    </message>
    <message>
        <source>Record a new session with this patient (%1)</source>
        <translation>Eine neue Sitzung mit diesem Patienten aufnehmen (%1)</translation>
    </message>
    <message>
        <source>Target (°)</source>
        <translation>Ziel (°)</translation>
    </message>
    <message>
        <source>Sets</source>
        <translation>Serien</translation>
    </message>
    <message>
        <source>Rest</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>%L1 × %L2</source>
        <translation>%L1 × %L2</translation>
    </message>
    <message>
        <source>%L1 s</source>
        <translation>%L1 s</translation>
    </message>
    <message>
        <source>%1 (oldest first)</source>
        <translation>%1 (älteste zuerst)</translation>
    </message>
    <message>
        <source>%1 (newest first)</source>
        <translation>%1 (neueste zuerst)</translation>
    </message>
    <message>
        <source>&amp;Delete session...</source>
        <translation>Sitzung &amp;löschen...</translation>
    </message>
    <message>
        <source>(%1)</source>
        <translation>(%1)</translation>
    </message>
    <message>
        <source>session %1</source>
        <translation>Sitzung %1</translation>
    </message>
    <message>
        <source>the session of %1 (%2, %3, session %4)</source>
        <translation>die Sitzung vom %1 (%2, %3, Sitzung %4)</translation>
    </message>
    <message>
        <source>free movement</source>
        <translation>freie Bewegung</translation>
    </message>
    <message>
        <source>Delete session</source>
        <translation>Sitzung löschen</translation>
    </message>
    <message>
        <source>Delete %1 of %2? Its recording, angles and metrics are removed for good; the audit log keeps that you did it.</source>
        <translation>%1 von %2 löschen? Aufzeichnung, Winkel und Kennwerte werden endgültig entfernt; das Prüfprotokoll hält fest, dass Sie es getan haben.</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Session %1 deleted.</source>
        <translation>Sitzung %1 gelöscht.</translation>
    </message>
    <message>
        <source>The session could not be deleted: %1</source>
        <translation>Die Sitzung konnte nicht gelöscht werden: %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientTableModel</name>
    <message>
        <source>female</source>
        <translation>weiblich</translation>
    </message>
    <message>
        <source>male</source>
        <translation>männlich</translation>
    </message>
    <message>
        <source>diverse</source>
        <translation>divers</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>both</source>
        <translation>beide</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Born</source>
        <translation>Geboren</translation>
    </message>
    <message>
        <source>Sex</source>
        <translation>Geschlecht</translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation>Betroffene Seite</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnose</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ProgressChart</name>
    <message>
        <source>Progress chart</source>
        <translation>Verlaufsdiagramm</translation>
    </message>
    <message>
        <source>Progress values</source>
        <translation>Verlaufswerte</translation>
    </message>
    <message>
        <source>rad</source>
        <translation>rad</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>Of normal</source>
        <translation>Vom Normwert</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sitzungen</translation>
    </message>
    <message>
        <source>%1: no analysed session yet</source>
        <translation>%1: noch keine ausgewertete Sitzung</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>%L1 %</source>
        <translation>%L1 %</translation>
    </message>
    <message>
        <source>d MMM</source>
        <comment>the date axis&apos; labels, a QDateTime format: day and short month</comment>
        <translation>d. MMM</translation>
    </message>
    <message>
        <source>Largest (%1)</source>
        <translation>Größter Winkel (%1)</translation>
    </message>
    <message>
        <source>Largest angle reached</source>
        <translation>Größter erreichter Winkel</translation>
    </message>
    <message>
        <source>Largest angle (%1)</source>
        <translation>Größter Winkel (%1)</translation>
    </message>
    <message>
        <source>&amp;Motion:</source>
        <translation>Be&amp;wegung:</translation>
    </message>
    <message>
        <source>Motion shown in the progress chart</source>
        <translation>Im Verlaufsdiagramm gezeigte Bewegung</translation>
    </message>
    <message>
        <source>The largest angle reached per session in the chosen motion, against date; the table beside it holds the same values.</source>
        <translation>Größter erreichter Winkel je Sitzung in der gewählten Bewegung, über dem Datum; die Tabelle daneben enthält dieselben Werte.</translation>
    </message>
    <message>
        <source>Shoulder extension</source>
        <translation>Schulterextension</translation>
    </message>
    <message>
        <source>Shoulder external rotation</source>
        <translation>Schulteraußenrotation</translation>
    </message>
    <message>
        <source>Forearm supination</source>
        <translation>Unterarmsupination</translation>
    </message>
    <message>
        <source>%1, opposite direction</source>
        <translation>%1, Gegenrichtung</translation>
    </message>
    <message>
        <source>Shoulder flexion</source>
        <translation>Schulterflexion</translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation>Schulterabduktion</translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation>Schulterinnenrotation</translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation>Ellenbogenflexion</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation>Unterarmpronation</translation>
    </message>
    <message>
        <source>Normal (%1) %L2 %3</source>
        <translation>Normbereich (%1) %L2 %3</translation>
    </message>
    <message>
        <source>Trunk flexion (compensation)</source>
        <translation>Rumpfflexion (Kompensation)</translation>
    </message>
    <message>
        <source>Largest trunk flexion (%1)</source>
        <translation>Größte Rumpfflexion (%1)</translation>
    </message>
    <message>
        <source>Largest trunk flexion</source>
        <translation>Größte Rumpfflexion</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RecordsRecordingTarget</name>
    <message>
        <source>the records of patient %1</source>
        <translation>die Akte von Patient %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RecordsService</name>
    <message>
        <source>The background connection to the records could not sign in (%1). Reports, exports and analyses will fail until you sign in again.</source>
        <translation>Die Hintergrundverbindung zu den Akten konnte sich nicht anmelden (%1). Berichte, Exporte und Auswertungen schlagen fehl, bis Sie sich erneut anmelden.</translation>
    </message>
    <message>
        <source>an unexpected error</source>
        <translation>ein unerwarteter Fehler</translation>
    </message>
    <message>
        <source>cannot create the folder %1: choose a folder you may write to</source>
        <translation>der Ordner %1 kann nicht angelegt werden: wählen Sie einen Ordner, in den Sie schreiben dürfen</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ReestimatePanel</name>
    <message>
        <source>Fuse the &amp;optical data (Kinect, webcam)</source>
        <translation>&amp;Optische Daten einbeziehen (Kinect, Webcam)</translation>
    </message>
    <message>
        <source>B&amp;rowse...</source>
        <translation>D&amp;urchsuchen ...</translation>
    </message>
    <message>
        <source>Re-&amp;estimate</source>
        <translation>Neu &amp;berechnen</translation>
    </message>
    <message>
        <source>Shown:</source>
        <translation>Angezeigt:</translation>
    </message>
    <message>
        <source>EKF (extended Kalman filter)</source>
        <translation>EKF (erweitertes Kalman-Filter)</translation>
    </message>
    <message>
        <source>UKF (unscented Kalman filter)</source>
        <translation>UKF (Unscented-Kalman-Filter)</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
    <message>
        <source>&amp;Filter:</source>
        <translation>&amp;Filter:</translation>
    </message>
    <message>
        <source>A: body acceleration modelled</source>
        <translation>A: Körperbeschleunigung modelliert</translation>
    </message>
    <message>
        <source>B: body acceleration as states</source>
        <translation>B: Körperbeschleunigung als Zustände</translation>
    </message>
    <message>
        <source>C: no compensation</source>
        <translation>C: ohne Kompensation</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>&amp;Methode:</translation>
    </message>
    <message>
        <source>none (a file from armtrack-cli calibrate)</source>
        <translation>keine (eine Datei von armtrack-cli calibrate)</translation>
    </message>
    <message>
        <source>Calibration file</source>
        <translation>Kalibrierungsdatei</translation>
    </message>
    <message>
        <source>&amp;Calibration:</source>
        <translation>&amp;Kalibrierung:</translation>
    </message>
    <message>
        <source>Calibrations (*.json)</source>
        <translation>Kalibrierungen (*.json)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RepetitionTableModel</name>
    <message>
        <source>partial</source>
        <translation>teilweise</translation>
    </message>
    <message>
        <source>full</source>
        <translation>vollständig</translation>
    </message>
    <message>
        <source>#</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>Beginn (s)</translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation>Ende (s)</translation>
    </message>
    <message>
        <source>Excursion (rad)</source>
        <translation>Exkursion (rad)</translation>
    </message>
    <message>
        <source>Range (rad)</source>
        <translation>Bewegungsausmaß (rad)</translation>
    </message>
    <message>
        <source>Peak velocity (rad/s)</source>
        <translation>Spitzengeschwindigkeit (rad/s)</translation>
    </message>
    <message>
        <source>SPARC</source>
        <translation>SPARC</translation>
    </message>
    <message>
        <source>Full or partial</source>
        <translation>Vollständig oder teilweise</translation>
    </message>
    <message>
        <source>Excursion (°)</source>
        <translation>Exkursion (°)</translation>
    </message>
    <message>
        <source>Range (°)</source>
        <translation>Bewegungsausmaß (°)</translation>
    </message>
    <message>
        <source>Peak velocity (°/s)</source>
        <translation>Spitzengeschwindigkeit (°/s)</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Trunk flexion (rad)</source>
        <translation>Rumpfflexion (rad)</translation>
    </message>
    <message>
        <source>Trunk flexion (°)</source>
        <translation>Rumpfflexion (°)</translation>
    </message>
    <message>
        <source>Lateral bending (rad)</source>
        <translation>Seitneigung (rad)</translation>
    </message>
    <message>
        <source>Lateral bending (°)</source>
        <translation>Seitneigung (°)</translation>
    </message>
    <message>
        <source>Axial rotation (rad)</source>
        <translation>Rumpfrotation (rad)</translation>
    </message>
    <message>
        <source>Axial rotation (°)</source>
        <translation>Rumpfrotation (°)</translation>
    </message>
    <message>
        <source>Shoulder displacement (cm)</source>
        <translation>Schulterverschiebung (cm)</translation>
    </message>
    <message>
        <source>Trunk compensation</source>
        <translation>Rumpfkompensation</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ReviewScreen</name>
    <message>
        <source>Review of session %1</source>
        <translation>Auswertung von Sitzung %1</translation>
    </message>
    <message>
        <source>Session %1</source>
        <translation>Sitzung %1</translation>
    </message>
    <message>
        <source>&amp;Back to the patient</source>
        <translation>&amp;Zurück zum Patienten</translation>
    </message>
    <message>
        <source>3D arm replay</source>
        <translation>3D-Wiedergabe des Arms</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Wiedergabe</translation>
    </message>
    <message>
        <source>Replay time</source>
        <translation>Wiedergabezeit</translation>
    </message>
    <message>
        <source>Replay speed</source>
        <translation>Wiedergabegeschwindigkeit</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>&amp;Repetitions</source>
        <translation>Wieder&amp;holungen</translation>
    </message>
    <message>
        <source>Session to compare with</source>
        <translation>Sitzung zum Vergleich</translation>
    </message>
    <message>
        <source>Another session of this patient, drawn dashed on the plots and as a translucent arm:</source>
        <translation>Eine andere Sitzung dieses Patienten, gestrichelt in den Diagrammen und als durchscheinender Arm gezeigt:</translation>
    </message>
    <message>
        <source>Co&amp;mpare</source>
        <translation>Ver&amp;gleichen</translation>
    </message>
    <message>
        <source>Session notes</source>
        <translation>Sitzungsnotizen</translation>
    </message>
    <message>
        <source>Sa&amp;ve notes</source>
        <translation>Notizen &amp;speichern</translation>
    </message>
    <message>
        <source>&amp;Notes</source>
        <translation>&amp;Notizen</translation>
    </message>
    <message>
        <source>Re-es&amp;timate</source>
        <translation>Neu &amp;berechnen</translation>
    </message>
    <message>
        <source>Report and e&amp;xport</source>
        <translation>Bericht und E&amp;xport</translation>
    </message>
    <message>
        <source>Reading the session...</source>
        <translation>Sitzung wird gelesen ...</translation>
    </message>
    <message>
        <source>This session could not be read: %1</source>
        <translation>Diese Sitzung konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>left arm</source>
        <translation>linker Arm</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>rechter Arm</translation>
    </message>
    <message>
        <source>%1: session of %2, %3</source>
        <translation>%1: Sitzung vom %2, %3</translation>
    </message>
    <message>
        <source>Review: %1, %2</source>
        <translation>Auswertung: %1, %2</translation>
    </message>
    <message>
        <source>not analysed yet</source>
        <translation>noch nicht ausgewertet</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) could not be read.</source>
        <translation>
            <numerusform>%n Wiederholung konnte nicht gelesen werden.</numerusform>
            <numerusform>%n Wiederholungen konnten nicht gelesen werden.</numerusform>
        </translation>
    </message>
    <message>
        <source>No metrics yet.</source>
        <translation>Noch keine Kennwerte.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Notes typed earlier were not saved; they are back in the Notes tab. Save them or edit them.</source>
        <translation>Früher eingegebene Notizen wurden nicht gespeichert; sie stehen wieder im Reiter „Notizen“. Speichern oder bearbeiten Sie sie.</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Session %1 has no analysis to compare with. Review it and re-estimate it first.</source>
        <translation>Sitzung %1 hat keine Auswertung zum Vergleichen. Öffnen Sie sie zuerst und berechnen Sie sie neu.</translation>
    </message>
    <message>
        <source>That session could not be read: %1</source>
        <translation>Diese Sitzung konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>Notes saved.</source>
        <translation>Notizen gespeichert.</translation>
    </message>
    <message>
        <source>The notes could not be saved: %1. They stay here and in a draft; try again.</source>
        <translation>Die Notizen konnten nicht gespeichert werden: %1. Sie bleiben hier und in einem Entwurf erhalten; versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>Estimating the joint angles again...</source>
        <translation>Gelenkwinkel werden neu berechnet ...</translation>
    </message>
    <message>
        <source>Re-estimation cancelled; nothing was stored.</source>
        <translation>Neuberechnung abgebrochen; nichts wurde gespeichert.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>New estimates stored as version %1.</source>
        <translation>Neue Berechnung als Version %1 gespeichert.</translation>
    </message>
    <message>
        <source>The session could not be estimated again: %1. The earlier estimates are kept.</source>
        <translation>Die Sitzung konnte nicht neu berechnet werden: %1. Die früheren Ergebnisse bleiben erhalten.</translation>
    </message>
    <message>
        <source>Save the session report</source>
        <translation>Sitzungsbericht speichern</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
    <message>
        <source>Folder of the BIDS data set</source>
        <translation>Ordner des BIDS-Datensatzes</translation>
    </message>
    <message>
        <source>Export as OpenSim motion</source>
        <translation>Als OpenSim-Bewegung exportieren</translation>
    </message>
    <message>
        <source>OpenSim motion (*.mot)</source>
        <translation>OpenSim-Bewegung (*.mot)</translation>
    </message>
    <message>
        <source>Export the angles as CSV</source>
        <translation>Winkel als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Export the recording</source>
        <translation>Aufnahme exportieren</translation>
    </message>
    <message>
        <source>Recordings (*.csv)</source>
        <translation>Aufnahmen (*.csv)</translation>
    </message>
    <message>
        <source>the session report</source>
        <translation>den Sitzungsbericht</translation>
    </message>
    <message numerus="yes">
        <source>Session report written: %1 (%n page(s)).</source>
        <translation>
            <numerusform>Sitzungsbericht geschrieben: %1 (%n Seite).</numerusform>
            <numerusform>Sitzungsbericht geschrieben: %1 (%n Seiten).</numerusform>
        </translation>
    </message>
    <message>
        <source>the export</source>
        <translation>den Export</translation>
    </message>
    <message>
        <source>Exported: %1.</source>
        <translation>Exportiert: %1.</translation>
    </message>
    <message>
        <source>Writing %1...</source>
        <translation>Schreibe %1 ...</translation>
    </message>
    <message>
        <source>%1 could not be written: %2. Choose another place and try again.</source>
        <translation>%1 konnte nicht geschrieben werden: %2. Wählen Sie einen anderen Ort und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>version %1 of %2: %3, method %4</source>
        <translation>Version %1 von %2: %3, Methode %4</translation>
    </message>
    <message>
        <source>, optical data fused</source>
        <translation>, optische Daten einbezogen</translation>
    </message>
    <message>
        <source>, no optical data fused</source>
        <translation>, ohne optische Daten</translation>
    </message>
    <message>
        <source>, calibrated</source>
        <translation>, kalibriert</translation>
    </message>
    <message>
        <source>Play or pause the replay (%1)</source>
        <translation>Wiedergabe starten oder anhalten (%1)</translation>
    </message>
    <message>
        <source>%L1×</source>
        <translation>%L1×</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) on %1 (%2 full, %3 partial). Smoothness: SPARC %4, LDLJ %5.</source>
        <translation>
            <numerusform>%n Wiederholung bei %1 (%2 vollständig, %3 teilweise). Glattheit: SPARC %4, LDLJ %5.</numerusform>
            <numerusform>%n Wiederholungen bei %1 (%2 vollständig, %3 teilweise). Glattheit: SPARC %4, LDLJ %5.</numerusform>
        </translation>
    </message>
    <message>
        <source>This session is waiting for its analysis, which ArmTrack runs in the background while a therapist is signed in: open the review again in a moment, or open &quot;Re-estimate&quot; to analyse it now.</source>
        <translation>Diese Sitzung wartet auf ihre Auswertung, die ArmTrack im Hintergrund ausführt, solange eine Therapeutin oder ein Therapeut angemeldet ist: Öffnen Sie die Ansicht gleich noch einmal, oder öffnen Sie „Neu berechnen“, um sie jetzt auszuwerten.</translation>
    </message>
    <message>
        <source>This session could not be analysed: %1. Open &quot;Re-estimate&quot; to try again, for example with other filter settings.</source>
        <translation>Diese Sitzung konnte nicht ausgewertet werden: %1. Öffnen Sie „Neu berechnen“, um es erneut zu versuchen, zum Beispiel mit anderen Filtereinstellungen.</translation>
    </message>
    <message>
        <source>no reason was stored</source>
        <translation>es wurde kein Grund gespeichert</translation>
    </message>
    <message>
        <source>This recording was cut short, so it was not analysed. Open &quot;Re-estimate&quot; to estimate its joint angles from what was recorded.</source>
        <translation>Diese Aufnahme wurde abgebrochen und daher nicht ausgewertet. Öffnen Sie „Neu berechnen“, um ihre Gelenkwinkel aus dem Aufgenommenen zu berechnen.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SessionSetupPage</name>
    <message>
        <source>&amp;Left arm</source>
        <translation>&amp;Linker Arm</translation>
    </message>
    <message>
        <source>&amp;Right arm</source>
        <translation>&amp;Rechter Arm</translation>
    </message>
    <message>
        <source>Patient, protocol and arm</source>
        <translation>Patient, Protokoll und Arm</translation>
    </message>
    <message>
        <source>Choose what this session trains and which arm wears the sensors.</source>
        <translation>Wählen Sie, was diese Sitzung trainiert und an welchem Arm die Sensoren sitzen.</translation>
    </message>
    <message>
        <source>Patient:</source>
        <translation>Patient:</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>(no protocol: free movement)</source>
        <translation>(kein Protokoll: freie Bewegung)</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protokoll:</translation>
    </message>
    <message>
        <source>Left arm</source>
        <translation>Linker Arm</translation>
    </message>
    <message>
        <source>Right arm</source>
        <translation>Rechter Arm</translation>
    </message>
    <message>
        <source>Arm:</source>
        <translation>Arm:</translation>
    </message>
    <message>
        <source>Reading the patient and the protocols...</source>
        <translation>Patient und Protokolle werden gelesen ...</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>The patient or the protocols could not be read: %1. Go back and try again.</source>
        <translation>Der Patient oder die Protokolle konnten nicht gelesen werden: %1. Gehen Sie zurück und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>Note: this protocol is meant for the %1 arm.</source>
        <translation>Hinweis: Dieses Protokoll ist für den %1 Arm gedacht.</translation>
    </message>
    <message>
        <source>left</source>
        <translation>linken</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechten</translation>
    </message>
    <message numerus="yes">
        <source>Trains %1, target %L2–%L3°, %n repetition(s).</source>
        <translation>
            <numerusform>Trainiert %1, Ziel %L2–%L3°, %n Wiederholung.</numerusform>
            <numerusform>Trainiert %1, Ziel %L2–%L3°, %n Wiederholungen.</numerusform>
        </translation>
    </message>
    <message>
        <source>No protocols are stored yet: an administrator adds them under ArmTrack &gt; Administration &gt; Protocols. Without one the session records free movement.</source>
        <translation>Es sind noch keine Protokolle gespeichert: Ein Administrator legt sie unter ArmTrack &gt; Verwaltung &gt; Protokolle an. Ohne Protokoll zeichnet die Sitzung freie Bewegung auf.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SessionTableModel</name>
    <message>
        <source>complete</source>
        <translation>vollständig</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>unterbrochen</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>läuft</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Started</source>
        <translation>Begonnen</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>IMU samples</source>
        <translation>IMU-Messwerte</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>home</source>
        <translation>zu Hause</translation>
    </message>
    <message>
        <source>clinic</source>
        <translation>Praxis</translation>
    </message>
    <message>
        <source>%L1 of %L2 repetitions</source>
        <translation>%L1 von %L2 Wiederholungen</translation>
    </message>
    <message>
        <source>%L1 of %L2 sets (not measured)</source>
        <translation>%L1 von %L2 Serien (nicht gemessen)</translation>
    </message>
    <message>
        <source>reached %L1° of %L2°</source>
        <translation>%L1° von %L2° erreicht</translation>
    </message>
    <message>
        <source>pain %L1/10</source>
        <translation>Schmerz %L1/10</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Patient&apos;s own account</source>
        <translation>Angaben des Patienten</translation>
    </message>
    <message>
        <source>complete, analysis pending</source>
        <translation>vollständig, Auswertung ausstehend</translation>
    </message>
    <message>
        <source>%1, cannot be analysed</source>
        <translation>%1, nicht auswertbar</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SettingsDialog</name>
    <message>
        <source>&amp;Add folder...</source>
        <translation>Ordner &amp;hinzufügen ...</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Anzeige</translation>
    </message>
    <message>
        <source>degrees</source>
        <translation>Grad</translation>
    </message>
    <message>
        <source>radians</source>
        <translation>Radiant</translation>
    </message>
    <message>
        <source>Angle units</source>
        <translation>Winkeleinheit</translation>
    </message>
    <message>
        <source>Angle &amp;units:</source>
        <translation>&amp;Winkeleinheit:</translation>
    </message>
    <message>
        <source>as the system</source>
        <translation>wie das System</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>light</source>
        <translation>hell</translation>
    </message>
    <message>
        <source>dark</source>
        <translation>dunkel</translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation>Erscheinungsbild</translation>
    </message>
    <message>
        <source>A&amp;ppearance:</source>
        <translation>&amp;Erscheinungsbild:</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <source>Data folder</source>
        <translation>Datenordner</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Durchsuchen ...</translation>
    </message>
    <message>
        <source>Data &amp;folder:</source>
        <translation>Daten&amp;ordner:</translation>
    </message>
    <message>
        <source>armtrack.db in the data folder</source>
        <translation>armtrack.db im Datenordner</translation>
    </message>
    <message>
        <source>A file path, sqlite:PATH, or postgresql://user@host:port/dbname</source>
        <translation>Ein Dateipfad, sqlite:PFAD oder postgresql://benutzer@host:port/dbname</translation>
    </message>
    <message>
        <source>Database</source>
        <translation>Datenbank</translation>
    </message>
    <message>
        <source>&amp;Database:</source>
        <translation>&amp;Datenbank:</translation>
    </message>
    <message>
        <source>Device plugin folders (searched before the built-in ones)</source>
        <translation>Ordner mit Geräte-Plugins (vor den eingebauten durchsucht)</translation>
    </message>
    <message>
        <source>Plugin folders</source>
        <translation>Plugin-Ordner</translation>
    </message>
    <message>
        <source>Estimation of new sessions</source>
        <translation>Berechnung neuer Sitzungen</translation>
    </message>
    <message>
        <source>EKF (extended Kalman filter)</source>
        <translation>EKF (erweitertes Kalman-Filter)</translation>
    </message>
    <message>
        <source>UKF (unscented Kalman filter)</source>
        <translation>UKF (Unscented-Kalman-Filter)</translation>
    </message>
    <message>
        <source>Default filter</source>
        <translation>Standardfilter</translation>
    </message>
    <message>
        <source>F&amp;ilter:</source>
        <translation>F&amp;ilter:</translation>
    </message>
    <message>
        <source>A: body acceleration modelled</source>
        <translation>A: Körperbeschleunigung modelliert</translation>
    </message>
    <message>
        <source>B: body acceleration as states</source>
        <translation>B: Körperbeschleunigung als Zustände</translation>
    </message>
    <message>
        <source>C: no compensation</source>
        <translation>C: ohne Kompensation</translation>
    </message>
    <message>
        <source>Default method</source>
        <translation>Standardmethode</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>&amp;Methode:</translation>
    </message>
    <message>
        <source>Plugin folder</source>
        <translation>Plugin-Ordner</translation>
    </message>
    <message>
        <source>Give the data folder as a full path, e.g. %1.</source>
        <translation>Geben Sie den Datenordner als vollständigen Pfad an, z. B. %1.</translation>
    </message>
    <message>
        <source>The database location is not one ArmTrack understands: %1</source>
        <translation>Diesen Speicherort der Datenbank versteht ArmTrack nicht: %1</translation>
    </message>
    <message>
        <source>The plugin folder %1 does not exist.</source>
        <translation>Der Plugin-Ordner %1 existiert nicht.</translation>
    </message>
    <message>
        <source>https://NAME:PORT (optional)</source>
        <translation>https://NAME:PORT (optional)</translation>
    </message>
    <message>
        <source>The clinic&apos;s sync server as patients type it on their home computer; shown with each enrolment code</source>
        <translation>Der Synchronisierungsserver der Praxis, wie Patienten ihn auf ihrem Computer zu Hause eingeben; wird mit jedem Anmeldecode angezeigt</translation>
    </message>
    <message>
        <source>Sync server address</source>
        <translation>Adresse des Synchronisierungsservers</translation>
    </message>
    <message>
        <source>S&amp;ync server address:</source>
        <translation>S&amp;ynchronisierungsserver:</translation>
    </message>
    <message>
        <source>Give the sync server address as https://NAME:PORT, e.g. https://sync.clinic.example:8443, or leave it empty.</source>
        <translation>Geben Sie die Adresse des Synchronisierungsservers als https://NAME:PORT an, z. B. https://sync.clinic.example:8443, oder lassen Sie das Feld leer.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SignInScreen</name>
    <message>
        <source>&amp;Sign in</source>
        <translation>&amp;Anmelden</translation>
    </message>
    <message>
        <source>Sign in</source>
        <translation>Anmelden</translation>
    </message>
    <message>
        <source>Sign in to ArmTrack</source>
        <translation>Bei ArmTrack anmelden</translation>
    </message>
    <message>
        <source>Records: %1</source>
        <translation>Akten: %1</translation>
    </message>
    <message>
        <source>Account name</source>
        <translation>Kontoname</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Passwort:</translation>
    </message>
    <message>
        <source>Type your account name.</source>
        <translation>Geben Sie Ihren Kontonamen ein.</translation>
    </message>
    <message>
        <source>Type your password.</source>
        <translation>Geben Sie Ihr Passwort ein.</translation>
    </message>
    <message>
        <source>Signing in...</source>
        <translation>Anmeldung läuft ...</translation>
    </message>
    <message>
        <source>Check the name and the password (is Caps Lock on?) and try again. If you have forgotten it, an administrator can set a new one.</source>
        <translation>Prüfen Sie Namen und Passwort (ist die Feststelltaste aktiv?) und versuchen Sie es erneut. Wenn Sie es vergessen haben, kann ein Administrator ein neues festlegen.</translation>
    </message>
    <message numerus="yes">
        <source>Wait %n s</source>
        <translation>
            <numerusform>Warten: %n s</numerusform>
            <numerusform>Warten: %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Too many wrong passwords for this account: wait %n s, then try again.</source>
        <translation>
            <numerusform>Zu viele falsche Passwörter für dieses Konto: warten Sie %n Sekunde und versuchen Sie es dann erneut.</numerusform>
            <numerusform>Zu viele falsche Passwörter für dieses Konto: warten Sie %n Sekunden und versuchen Sie es dann erneut.</numerusform>
        </translation>
    </message>
    <message>
        <source>Wrong user name or password.</source>
        <translation>Falscher Benutzername oder falsches Passwort.</translation>
    </message>
    <message>
        <source>Too many wrong passwords for this account. You may try again now.</source>
        <translation>Zu viele falsche Passwörter für dieses Konto. Sie können es jetzt erneut versuchen.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::TrunkPanel</name>
    <message>
        <source>Trunk</source>
        <translation>Rumpf</translation>
    </message>
    <message>
        <source>Largest trunk flexion:</source>
        <translation>Größte Rumpfflexion:</translation>
    </message>
    <message>
        <source>Largest lateral bending:</source>
        <translation>Größte Seitneigung:</translation>
    </message>
    <message>
        <source>Largest axial rotation:</source>
        <translation>Größte Rumpfrotation:</translation>
    </message>
    <message>
        <source>Largest shoulder displacement:</source>
        <translation>Größte Schulterverschiebung:</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>%L1 rad</source>
        <translation>%L1 rad</translation>
    </message>
    <message>
        <source>%L1°</source>
        <translation>%L1°</translation>
    </message>
    <message>
        <source>%L1 cm</source>
        <translation>%L1 cm</translation>
    </message>
    <message>
        <source>Repetitions with compensation:</source>
        <translation>Wiederholungen mit Kompensation:</translation>
    </message>
    <message>
        <source>%1 of %2 (flexion over %3)</source>
        <translation>%1 von %2 (Flexion über %3)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::AccountDialog</name>
    <message>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message>
        <source>Password again</source>
        <translation>Passwort wiederholen</translation>
    </message>
    <message>
        <source>New account</source>
        <translation>Neues Konto</translation>
    </message>
    <message>
        <source>Account name</source>
        <translation>Kontoname</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>Patient of the home account</source>
        <translation>Patient des Heimkontos</translation>
    </message>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Role:</source>
        <translation>&amp;Rolle:</translation>
    </message>
    <message>
        <source>Pa&amp;tient (home account):</source>
        <translation>Pa&amp;tient (Heimkonto):</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Passwort:</translation>
    </message>
    <message>
        <source>Password &amp;again:</source>
        <translation>Passwort &amp;wiederholen:</translation>
    </message>
    <message>
        <source>Give the account a name, e.g. the person&apos;s first name and initial.</source>
        <translation>Geben Sie dem Konto einen Namen, z. B. Vorname und Initiale der Person.</translation>
    </message>
    <message>
        <source>A home account belongs to one patient: add the patient first, then choose them.</source>
        <translation>Ein Heimkonto gehört zu einem Patienten: Legen Sie zuerst den Patienten an und wählen Sie ihn dann.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::AccountsPage</name>
    <message>
        <source>Accounts</source>
        <translation>Konten</translation>
    </message>
    <message>
        <source>&amp;Add account...</source>
        <translation>Konto &amp;hinzufügen...</translation>
    </message>
    <message>
        <source>Reset &amp;password...</source>
        <translation>&amp;Passwort zurücksetzen...</translation>
    </message>
    <message>
        <source>Re&amp;move account...</source>
        <translation>Konto &amp;entfernen...</translation>
    </message>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>Patient (home accounts)</source>
        <translation>Patient (Heimkonten)</translation>
    </message>
    <message>
        <source>Account %1 (%2) added: they can sign in now.</source>
        <translation>Konto %1 (%2) angelegt: Es kann sich jetzt anmelden.</translation>
    </message>
    <message>
        <source>Choose the account whose password to reset.</source>
        <translation>Wählen Sie das Konto, dessen Passwort zurückgesetzt werden soll.</translation>
    </message>
    <message>
        <source>The password of %1 is reset. Tell them the new one in person.</source>
        <translation>Das Passwort von %1 ist zurückgesetzt. Teilen Sie das neue persönlich mit.</translation>
    </message>
    <message>
        <source>Choose the account to remove.</source>
        <translation>Wählen Sie das Konto, das entfernt werden soll.</translation>
    </message>
    <message>
        <source>Remove account</source>
        <translation>Konto entfernen</translation>
    </message>
    <message>
        <source>Remove the account %1? They can no longer sign in. The sessions they recorded stay.</source>
        <translation>Konto %1 entfernen? Es kann sich dann nicht mehr anmelden. Die damit aufgezeichneten Sitzungen bleiben.</translation>
    </message>
    <message>
        <source>Account %1 removed.</source>
        <translation>Konto %1 entfernt.</translation>
    </message>
    <message>
        <source>&amp;Enable account</source>
        <translation>Konto &amp;freigeben</translation>
    </message>
    <message>
        <source>D&amp;isable account...</source>
        <translation>Konto &amp;sperren...</translation>
    </message>
    <message>
        <source>Disabled</source>
        <translation>Gesperrt</translation>
    </message>
    <message>
        <source>Active</source>
        <translation>Aktiv</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Choose the account to disable or enable.</source>
        <translation>Wählen Sie das Konto, das gesperrt oder freigegeben werden soll.</translation>
    </message>
    <message>
        <source>Account %1 disabled: it can no longer sign in. Its sessions and history keep its name.</source>
        <translation>Konto %1 gesperrt: Es kann sich nicht mehr anmelden. Seine Sitzungen und sein Verlauf behalten den Namen.</translation>
    </message>
    <message>
        <source>Account %1 enabled: it can sign in again.</source>
        <translation>Konto %1 freigegeben: Es kann sich wieder anmelden.</translation>
    </message>
    <message>
        <source>Disable account</source>
        <translation>Konto sperren</translation>
    </message>
    <message>
        <source>Disable the account %1? It can no longer sign in until an administrator enables it again. Its sessions and history stay, under its name.</source>
        <translation>Das Konto %1 sperren? Es kann sich nicht mehr anmelden, bis ein Administrator es wieder freigibt. Seine Sitzungen und sein Verlauf bleiben unter seinem Namen erhalten.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::AdminScreen</name>
    <message>
        <source>Administration</source>
        <translation>Verwaltung</translation>
    </message>
    <message>
        <source>&amp;Accounts</source>
        <translation>&amp;Konten</translation>
    </message>
    <message>
        <source>P&amp;rotocols</source>
        <translation>P&amp;rotokolle</translation>
    </message>
    <message>
        <source>&amp;Home programmes</source>
        <translation>&amp;Heimprogramme</translation>
    </message>
    <message>
        <source>Back to the patients</source>
        <translation>Zurück zu den Patienten</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ExerciseDialog</name>
    <message>
        <source>Its own &amp;target range</source>
        <translation>Eigener &amp;Zielbereich</translation>
    </message>
    <message>
        <source>Target from</source>
        <translation>Ziel von</translation>
    </message>
    <message>
        <source>Target to</source>
        <translation>Ziel bis</translation>
    </message>
    <message>
        <source>Edit exercise %1</source>
        <translation>Übung %1 bearbeiten</translation>
    </message>
    <message>
        <source>New exercise</source>
        <translation>Neue Übung</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Sets</source>
        <translation>Sätze</translation>
    </message>
    <message>
        <source>Repetitions per set</source>
        <translation>Wiederholungen pro Satz</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Rest between sets</source>
        <translation>Pause zwischen Sätzen</translation>
    </message>
    <message>
        <source>Sessions per week</source>
        <translation>Sitzungen pro Woche</translation>
    </message>
    <message>
        <source>Notes for the patient</source>
        <translation>Hinweise für den Patienten</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protokoll:</translation>
    </message>
    <message>
        <source>S&amp;ets:</source>
        <translation>Sätz&amp;e:</translation>
    </message>
    <message>
        <source>&amp;Repetitions per set:</source>
        <translation>&amp;Wiederholungen pro Satz:</translation>
    </message>
    <message>
        <source>Target &amp;from:</source>
        <translation>Ziel &amp;von:</translation>
    </message>
    <message>
        <source>Target &amp;to:</source>
        <translation>Ziel &amp;bis:</translation>
    </message>
    <message>
        <source>Re&amp;st between sets:</source>
        <translation>Pa&amp;use zwischen Sätzen:</translation>
    </message>
    <message>
        <source>Sessions per &amp;week:</source>
        <translation>Sitzungen pro &amp;Woche:</translation>
    </message>
    <message>
        <source>&amp;Notes:</source>
        <translation>&amp;Hinweise:</translation>
    </message>
    <message>
        <source>the protocol&apos;s (%1)</source>
        <translation>die des Protokolls (%1)</translation>
    </message>
    <message>
        <source>the protocol&apos;s</source>
        <translation>die des Protokolls</translation>
    </message>
    <message>
        <source>There is no protocol yet: add one on the Protocols page first.</source>
        <translation>Es gibt noch kein Protokoll: Legen Sie zuerst eines auf der Seite Protokolle an.</translation>
    </message>
    <message>
        <source>The target ends below where it starts: make &quot;to&quot; at least &quot;from&quot;.</source>
        <translation>Das Ziel endet unter seinem Anfang: „bis“ muss mindestens „von“ sein.</translation>
    </message>
    <message>
        <source>Tr&amp;unk limit:</source>
        <translation>R&amp;umpfgrenze:</translation>
    </message>
    <message>
        <source>the protocol&apos;s (%1 deg)</source>
        <translation>die des Protokolls (%1°)</translation>
    </message>
    <message>
        <source>the protocol&apos;s (off)</source>
        <translation>die des Protokolls (aus)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::FormDialog</name>
    <message>
        <source> deg</source>
        <translation> Grad</translation>
    </message>
    <message>
        <source>Choose a password of at least %1 characters.</source>
        <translation>Wählen Sie ein Passwort mit mindestens %1 Zeichen.</translation>
    </message>
    <message>
        <source>The two passwords differ: type the same password twice.</source>
        <translation>Die beiden Passwörter unterscheiden sich: Geben Sie zweimal dasselbe Passwort ein.</translation>
    </message>
    <message>
        <source>administrator</source>
        <translation>Administrator</translation>
    </message>
    <message>
        <source>therapist</source>
        <translation>Therapeut</translation>
    </message>
    <message>
        <source>home account</source>
        <translation>Heimkonto</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Saving...</source>
        <translation>Wird gespeichert...</translation>
    </message>
    <message>
        <source>Trunk limit</source>
        <translation>Rumpfgrenze</translation>
    </message>
    <message>
        <source>Degrees of trunk flexion: leaning further, the patient is told &quot;Keep your back against the chair&quot; and the repetition counts as made with compensation. Needs a trunk sensor.</source>
        <translation>Grad Rumpfflexion: Neigt sich der Patient weiter, heißt es „Lehnen Sie den Rücken an den Stuhl“, und die Wiederholung zählt als mit Kompensation ausgeführt. Braucht einen Rumpfsensor.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::PasswordDialog</name>
    <message>
        <source>New password</source>
        <translation>Neues Passwort</translation>
    </message>
    <message>
        <source>New password again</source>
        <translation>Neues Passwort wiederholen</translation>
    </message>
    <message>
        <source>New password for %1</source>
        <translation>Neues Passwort für %1</translation>
    </message>
    <message>
        <source>&amp;New password:</source>
        <translation>&amp;Neues Passwort:</translation>
    </message>
    <message>
        <source>Password &amp;again:</source>
        <translation>Passwort &amp;wiederholen:</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ProgrammePage</name>
    <message>
        <source>Pa&amp;tient:</source>
        <translation>Pa&amp;tient:</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patient</translation>
    </message>
    <message>
        <source>Home programme</source>
        <translation>Heimprogramm</translation>
    </message>
    <message>
        <source>&amp;Add exercise...</source>
        <translation>Übung &amp;hinzufügen...</translation>
    </message>
    <message>
        <source>&amp;Edit exercise...</source>
        <translation>Übung &amp;bearbeiten...</translation>
    </message>
    <message>
        <source>Re&amp;move exercise...</source>
        <translation>Übung &amp;entfernen...</translation>
    </message>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>There are no patients yet: add them on the patient list first.</source>
        <translation>Es gibt noch keine Patienten: Legen Sie sie zuerst in der Patientenliste an.</translation>
    </message>
    <message>
        <source>%1 x %2</source>
        <translation>%1 x %2</translation>
    </message>
    <message>
        <source>%1 to %2 deg</source>
        <translation>%1 bis %2 Grad</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>Sets x repetitions</source>
        <translation>Sätze x Wiederholungen</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Rest</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Per week</source>
        <translation>Pro Woche</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Hinweise</translation>
    </message>
    <message>
        <source>Choose a patient first.</source>
        <translation>Wählen Sie zuerst einen Patienten.</translation>
    </message>
    <message>
        <source>Choose the exercise to edit.</source>
        <translation>Wählen Sie die Übung, die bearbeitet werden soll.</translation>
    </message>
    <message>
        <source>There is no protocol yet: add one on the Protocols page first.</source>
        <translation>Es gibt noch kein Protokoll: Legen Sie zuerst eines auf der Seite Protokolle an.</translation>
    </message>
    <message>
        <source>%1 is in the home programme of %2.</source>
        <translation>%1 ist im Heimprogramm von %2.</translation>
    </message>
    <message>
        <source>Choose the exercise to remove.</source>
        <translation>Wählen Sie die Übung, die entfernt werden soll.</translation>
    </message>
    <message>
        <source>Remove exercise</source>
        <translation>Übung entfernen</translation>
    </message>
    <message>
        <source>Remove %1 from the home programme of %2? The sessions already done stay.</source>
        <translation>%1 aus dem Heimprogramm von %2 entfernen? Bereits gemachte Sitzungen bleiben.</translation>
    </message>
    <message>
        <source>%1 removed from the programme.</source>
        <translation>%1 aus dem Programm entfernt.</translation>
    </message>
    <message>
        <source>%1 deg</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>Trunk limit</source>
        <translation>Rumpfgrenze</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ProtocolDialog</name>
    <message>
        <source>Target from</source>
        <translation>Ziel von</translation>
    </message>
    <message>
        <source>Target to</source>
        <translation>Ziel bis</translation>
    </message>
    <message>
        <source>New protocol</source>
        <translation>Neues Protokoll</translation>
    </message>
    <message>
        <source>Edit protocol %1</source>
        <translation>Protokoll %1 bearbeiten</translation>
    </message>
    <message>
        <source>Protocol name</source>
        <translation>Protokollname</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Seite</translation>
    </message>
    <message>
        <source>either arm</source>
        <translation>beide Arme</translation>
    </message>
    <message>
        <source>left arm</source>
        <translation>linker Arm</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>rechter Arm</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Angle:</source>
        <translation>&amp;Winkel:</translation>
    </message>
    <message>
        <source>Target &amp;from:</source>
        <translation>Ziel &amp;von:</translation>
    </message>
    <message>
        <source>Target &amp;to:</source>
        <translation>Ziel &amp;bis:</translation>
    </message>
    <message>
        <source>&amp;Repetitions:</source>
        <translation>&amp;Wiederholungen:</translation>
    </message>
    <message>
        <source>&amp;Side:</source>
        <translation>&amp;Seite:</translation>
    </message>
    <message>
        <source>Give the protocol a name, e.g. &quot;Shoulder flexion to 120&quot;.</source>
        <translation>Geben Sie dem Protokoll einen Namen, z. B. „Schulterflexion bis 120“.</translation>
    </message>
    <message>
        <source>The target ends below where it starts: make &quot;to&quot; at least &quot;from&quot;.</source>
        <translation>Das Ziel endet unter seinem Anfang: „bis“ muss mindestens „von“ sein.</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Tr&amp;unk limit:</source>
        <translation>R&amp;umpfgrenze:</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ProtocolsPage</name>
    <message>
        <source>left arm</source>
        <translation>linker Arm</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>rechter Arm</translation>
    </message>
    <message>
        <source>either arm</source>
        <translation>beide Arme</translation>
    </message>
    <message>
        <source>Protocols</source>
        <translation>Protokolle</translation>
    </message>
    <message>
        <source>&amp;Add protocol...</source>
        <translation>Protokoll &amp;hinzufügen...</translation>
    </message>
    <message>
        <source>&amp;Edit protocol...</source>
        <translation>Protokoll &amp;bearbeiten...</translation>
    </message>
    <message>
        <source>%1 to %2 deg</source>
        <translation>%1 bis %2 Grad</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Seite</translation>
    </message>
    <message>
        <source>Choose the protocol to edit.</source>
        <translation>Wählen Sie das Protokoll, das bearbeitet werden soll.</translation>
    </message>
    <message>
        <source>Protocol %1 added: it is offered in new sessions and programmes.</source>
        <translation>Protokoll %1 angelegt: Es wird in neuen Sitzungen und Programmen angeboten.</translation>
    </message>
    <message>
        <source>Protocol %1 saved.</source>
        <translation>Protokoll %1 gespeichert.</translation>
    </message>
    <message>
        <source>%1 deg</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>Trunk limit</source>
        <translation>Rumpfgrenze</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::ExerciseRecording</name>
    <message>
        <source>the records</source>
        <translation>die Akten</translation>
    </message>
    <message>
        <source>This exercise cannot be saved: %1</source>
        <translation>Diese Übung kann nicht gespeichert werden: %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::ExerciseScreen</name>
    <message>
        <source>The sensors could not start: %1. Check that they are switched on; you can skip this exercise.</source>
        <translation>Die Sensoren konnten nicht starten: %1. Prüfen Sie, ob sie eingeschaltet sind; Sie können diese Übung überspringen.</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>Exercise %L1 of %L2: %3</source>
        <translation>Übung %L1 von %L2: %3</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Anweisung</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>Your angle now</source>
        <translation>Ihr Winkel jetzt</translation>
    </message>
    <message>
        <source>Feedback</source>
        <translation>Rückmeldung</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Pause (Escape)</source>
        <translation>Pause (Esc)</translation>
    </message>
    <message>
        <source>S&amp;kip this exercise</source>
        <translation>Übung übers&amp;pringen</translation>
    </message>
    <message>
        <source>S&amp;top for today</source>
        <translation>Für heute &amp;beenden</translation>
    </message>
    <message>
        <source>%1: not measured</source>
        <translation>%1: nicht gemessen</translation>
    </message>
    <message>
        <source>Raise your arm forward with the elbow straight, up to where the light arm goes, then lower it slowly.</source>
        <translation>Heben Sie den Arm mit gestrecktem Ellbogen nach vorn, so weit wie der helle Arm, und senken Sie ihn dann langsam.</translation>
    </message>
    <message>
        <source>Raise your arm out to the side with the elbow straight, up to where the light arm goes, then lower it slowly.</source>
        <translation>Heben Sie den Arm mit gestrecktem Ellbogen seitlich an, so weit wie der helle Arm, und senken Sie ihn dann langsam.</translation>
    </message>
    <message>
        <source>Keep your elbow at your side, bent at a right angle. Turn your hand in towards your belly and out again, as the light arm does.</source>
        <translation>Halten Sie den Ellbogen rechtwinklig gebeugt am Körper. Drehen Sie die Hand zum Bauch hin und wieder nach außen, wie der helle Arm.</translation>
    </message>
    <message>
        <source>Bend your elbow up as far as the light arm goes, then straighten it slowly. Keep your upper arm still.</source>
        <translation>Beugen Sie den Ellbogen so weit wie der helle Arm und strecken Sie ihn dann langsam. Halten Sie den Oberarm ruhig.</translation>
    </message>
    <message>
        <source>Keep your elbow bent at a right angle. Turn your palm down and up again, as the light arm does.</source>
        <translation>Halten Sie den Ellbogen rechtwinklig gebeugt. Drehen Sie die Handfläche nach unten und wieder nach oben, wie der helle Arm.</translation>
    </message>
    <message numerus="yes">
        <source>Then press Start: %n set(s) of %1 repetitions.</source>
        <translation>
            <numerusform>Drücken Sie dann Start: %n Serie mit %1 Wiederholungen.</numerusform>
            <numerusform>Drücken Sie dann Start: %n Serien mit %1 Wiederholungen.</numerusform>
        </translation>
    </message>
    <message>
        <source>ArmTrack cannot measure this exercise without the camera. Do it as shown and count the repetitions yourself; it is recorded for your therapist.</source>
        <translation>Ohne die Kamera kann ArmTrack diese Übung nicht messen. Machen Sie sie wie gezeigt und zählen Sie die Wiederholungen selbst; sie wird für Ihre Therapeutin aufgezeichnet.</translation>
    </message>
    <message>
        <source>Your therapist says: %1</source>
        <translation>Ihre Therapeutin sagt: %1</translation>
    </message>
    <message>
        <source>&amp;Start set %1</source>
        <translation>Serie %1 &amp;starten</translation>
    </message>
    <message>
        <source>Set %1 of %2: move like the light arm, %3 times. Take your time.</source>
        <translation>Serie %1 von %2: Bewegen Sie sich wie der helle Arm, %3-mal. Lassen Sie sich Zeit.</translation>
    </message>
    <message>
        <source>Set %1 of %2: do the movement %3 times, then press Done.</source>
        <translation>Serie %1 von %2: Machen Sie die Bewegung %3-mal und drücken Sie dann Fertig.</translation>
    </message>
    <message>
        <source>&amp;Done with this set</source>
        <translation>Serie &amp;fertig</translation>
    </message>
    <message>
        <source>&amp;Start the next set now</source>
        <translation>Nächste Serie jetzt &amp;starten</translation>
    </message>
    <message>
        <source>Paused. Press Go on when you are ready.</source>
        <translation>Angehalten. Drücken Sie Weiter, wenn Sie bereit sind.</translation>
    </message>
    <message>
        <source>&amp;Go on</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <source>Saving this exercise…</source>
        <translation>Diese Übung wird gespeichert …</translation>
    </message>
    <message>
        <source>Rest: %1 s</source>
        <translation>Pause: %1 s</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <source>Count: %1 times</source>
        <translation>Zählen Sie: %1-mal</translation>
    </message>
    <message>
        <source>Set %1 of %2</source>
        <translation>Serie %1 von %2</translation>
    </message>
    <message>
        <source>Set %1 done. Well done!</source>
        <translation>Serie %1 geschafft. Gut gemacht!</translation>
    </message>
    <message>
        <source>The camera does not see you, so ArmTrack cannot measure this shoulder exercise now. Go on as shown, count yourself, and press Done after each set.</source>
        <translation>Die Kamera sieht Sie nicht, deshalb kann ArmTrack diese Schulterübung jetzt nicht messen. Machen Sie wie gezeigt weiter, zählen Sie selbst und drücken Sie nach jeder Serie Fertig.</translation>
    </message>
    <message>
        <source>%1: %2°</source>
        <translation>%1: %2°</translation>
    </message>
    <message>
        <source>Target reached!</source>
        <translation>Ziel erreicht!</translation>
    </message>
    <message>
        <source>Good: %1 done.</source>
        <translation>Gut: %1 geschafft.</translation>
    </message>
    <message>
        <source>Try to go a little further next time.</source>
        <translation>Versuchen Sie, beim nächsten Mal etwas weiter zu gehen.</translation>
    </message>
    <message>
        <source>Almost: go a little further for it to count.</source>
        <translation>Fast: Gehen Sie etwas weiter, damit es zählt.</translation>
    </message>
    <message>
        <source>A little slower, please.</source>
        <translation>Etwas langsamer, bitte.</translation>
    </message>
    <message>
        <source>Keep your elbow straight; move only your shoulder.</source>
        <translation>Halten Sie den Ellbogen gestreckt; bewegen Sie nur die Schulter.</translation>
    </message>
    <message>
        <source>Keep your upper arm still; move only your elbow and forearm.</source>
        <translation>Halten Sie den Oberarm ruhig; bewegen Sie nur Ellbogen und Unterarm.</translation>
    </message>
    <message>
        <source>Trunk cue</source>
        <translation>Hinweis zum Rumpf</translation>
    </message>
    <message>
        <source>Repetitions leaning too far</source>
        <translation>Wiederholungen zu weit geneigt</translation>
    </message>
    <message>
        <source>Keep your back against the chair</source>
        <translation>Lehnen Sie den Rücken an den Stuhl</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) leaning too far</source>
        <translation>
            <numerusform>%n Wiederholung zu weit geneigt</numerusform>
            <numerusform>%n Wiederholungen zu weit geneigt</numerusform>
        </translation>
    </message>
    <message>
        <source>Rest with your upper arm hanging, your elbow bent at a right angle and your thumb up. The next set starts by itself when the time is up.</source>
        <translation>Ruhen Sie mit hängendem Oberarm, rechtwinklig gebeugtem Ellbogen und dem Daumen nach oben. Die nächste Serie beginnt von selbst, wenn die Zeit um ist.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeCalibrationScreen</name>
    <message>
        <source>Now ArmTrack learns how the sensors sit on your arm today. It takes about a minute: press Start, then do what the screen says and what the light arm shows.</source>
        <translation>Jetzt lernt ArmTrack, wie die Sensoren heute an Ihrem Arm sitzen. Das dauert etwa eine Minute: Drücken Sie Start und tun Sie dann, was der Bildschirm sagt und der helle Arm zeigt.</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <source>S&amp;kip the calibration</source>
        <translation>Kalibrierung übers&amp;pringen</translation>
    </message>
    <message>
        <source>&amp;Go on</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <source>&amp;Go on without it</source>
        <translation>&amp;Ohne sie weiter</translation>
    </message>
    <message>
        <source>Skip the calibration?</source>
        <translation>Die Kalibrierung überspringen?</translation>
    </message>
    <message>
        <source>Do you want to go on without the calibration?</source>
        <translation>Möchten Sie ohne die Kalibrierung weitermachen?</translation>
    </message>
    <message>
        <source>Without it, ArmTrack measures your arm a little less exactly today. The calibration takes about a minute.</source>
        <translation>Ohne sie misst ArmTrack Ihren Arm heute etwas weniger genau. Die Kalibrierung dauert etwa eine Minute.</translation>
    </message>
    <message>
        <source>&amp;Skip it</source>
        <translation>Ü&amp;berspringen</translation>
    </message>
    <message>
        <source>&amp;Do the calibration</source>
        <translation>&amp;Kalibrierung machen</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeConnectScreen</name>
    <message>
        <source>Connect to the clinic</source>
        <translation>Mit der Klinik verbinden</translation>
    </message>
    <message>
        <source>Your therapist gives you the clinic&apos;s address and a code. Once connected, your sessions are sent to your therapist and your exercises come from the clinic. You can always exercise without a connection: sessions are kept and sent later.</source>
        <translation>Ihre Therapeutin oder Ihr Therapeut gibt Ihnen die Adresse der Klinik und einen Code. Sobald die Verbindung besteht, werden Ihre Sitzungen an die Therapie gesendet, und Ihre Übungen kommen von der Klinik. Sie können immer auch ohne Verbindung üben: Die Sitzungen werden aufbewahrt und später gesendet.</translation>
    </message>
    <message>
        <source>Clinic&apos;s &amp;address (for example sync.clinic.example:8443)</source>
        <translation>&amp;Adresse der Klinik (zum Beispiel sync.clinic.example:8443)</translation>
    </message>
    <message>
        <source>&amp;Code from your therapist</source>
        <translation>&amp;Code aus der Therapie</translation>
    </message>
    <message>
        <source>Clinic&apos;s address</source>
        <translation>Adresse der Klinik</translation>
    </message>
    <message>
        <source>Code from your therapist</source>
        <translation>Code aus der Therapie</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Zurück</translation>
    </message>
    <message>
        <source>Type the clinic&apos;s address and the code, then press Connect.</source>
        <translation>Geben Sie die Adresse der Klinik und den Code ein und drücken Sie dann „Verbinden“.</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Verbindung wird hergestellt…</translation>
    </message>
    <message>
        <source>Not connected to a clinic: sessions are kept on this computer</source>
        <translation>Nicht mit einer Klinik verbunden: Die Sitzungen bleiben auf diesem Computer</translation>
    </message>
    <message>
        <source>Sending to the clinic…</source>
        <translation>Wird an die Klinik gesendet…</translation>
    </message>
    <message>
        <source>The clinic&apos;s server is not the one connected before: nothing was sent. Sessions are kept; call your therapist.</source>
        <translation>Der Server der Klinik ist nicht derselbe wie zuvor: Es wurde nichts gesendet. Die Sitzungen bleiben erhalten; rufen Sie Ihre Therapie an.</translation>
    </message>
    <message>
        <source>The clinic no longer accepts this computer: sessions are kept. Call your therapist.</source>
        <translation>Die Klinik nimmt diesen Computer nicht mehr an: Die Sitzungen bleiben erhalten. Rufen Sie Ihre Therapie an.</translation>
    </message>
    <message>
        <source>Not connected: sessions are kept and sent later</source>
        <translation>Nicht verbunden: Die Sitzungen werden aufbewahrt und später gesendet</translation>
    </message>
    <message numerus="yes">
        <source>%n session(s) waiting to be sent</source>
        <translation>
            <numerusform>%n Sitzung wartet auf das Senden</numerusform>
            <numerusform>%n Sitzungen warten auf das Senden</numerusform>
        </translation>
    </message>
    <message>
        <source>Everything is sent</source>
        <translation>Alles ist gesendet</translation>
    </message>
    <message>
        <source>Sent today %1</source>
        <translation>Heute gesendet um %1</translation>
    </message>
    <message>
        <source>Last sent %1</source>
        <translation>Zuletzt gesendet: %1</translation>
    </message>
    <message>
        <source>Connected to the clinic. Your sessions will be sent there.</source>
        <translation>Mit der Klinik verbunden. Ihre Sitzungen werden dorthin gesendet.</translation>
    </message>
    <message>
        <source>The clinic&apos;s server cannot be reached: check the address and the internet connection, then try again.</source>
        <translation>Der Server der Klinik ist nicht erreichbar: Prüfen Sie die Adresse und die Internetverbindung und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>The code is wrong, used or expired: ask your therapist for a new one.</source>
        <translation>Der Code ist falsch, schon benutzt oder abgelaufen: Bitten Sie Ihre Therapie um einen neuen.</translation>
    </message>
    <message>
        <source>This computer cannot keep the connection (%1): call your therapist.</source>
        <translation>Dieser Computer kann die Verbindung nicht speichern (%1): Rufen Sie Ihre Therapie an.</translation>
    </message>
    <message>
        <source>The clinic&apos;s server did not accept it (%1): try again, or call your therapist.</source>
        <translation>Der Server der Klinik hat es nicht angenommen (%1): Versuchen Sie es erneut oder rufen Sie Ihre Therapie an.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeController</name>
    <message>
        <source>One moment</source>
        <translation>Einen Moment</translation>
    </message>
    <message>
        <source>Loading today&apos;s exercises…</source>
        <translation>Die heutigen Übungen werden geladen …</translation>
    </message>
    <message>
        <source>Today</source>
        <translation>Heute</translation>
    </message>
    <message>
        <source>Sensor check</source>
        <translation>Sensorprüfung</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <source>Exercise %L1 of %L2</source>
        <translation>Übung %L1 von %L2</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>Something went wrong</source>
        <translation>Etwas ist schiefgegangen</translation>
    </message>
    <message>
        <source>%1
Please try again. If this happens again, call your therapist.</source>
        <translation>%1
Bitte versuchen Sie es noch einmal. Wenn das wieder passiert, rufen Sie Ihre Therapeutin an.</translation>
    </message>
    <message>
        <source>&amp;Try again</source>
        <translation>&amp;Erneut versuchen</translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation>&amp;Abmelden</translation>
    </message>
    <message>
        <source>cannot create a temporary folder for the sensor check (%1): free some disk space</source>
        <translation>für die Sensorprüfung kann kein temporärer Ordner angelegt werden (%1): geben Sie Speicherplatz frei</translation>
    </message>
    <message>
        <source>Stop this exercise?</source>
        <translation>Diese Übung beenden?</translation>
    </message>
    <message>
        <source>Do you want to stop for today?</source>
        <translation>Möchten Sie für heute aufhören?</translation>
    </message>
    <message>
        <source>What you have done so far is saved for your therapist. You can also keep exercising.</source>
        <translation>Was Sie bisher gemacht haben, wird für Ihre Therapeutin oder Ihren Therapeuten gespeichert. Sie können auch weiter üben.</translation>
    </message>
    <message>
        <source>&amp;Stop and save</source>
        <translation>&amp;Stoppen und speichern</translation>
    </message>
    <message>
        <source>&amp;Keep exercising</source>
        <translation>&amp;Weiter üben</translation>
    </message>
    <message>
        <source>Clinic</source>
        <translation>Klinik</translation>
    </message>
    <message>
        <source>home computer</source>
        <translation>Computer zu Hause</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeStartScreen</name>
    <message numerus="yes">
        <source>%1: %n set(s) of %2 repetitions, %3 s rest</source>
        <translation>
            <numerusform>%1: %n Serie mit %2 Wiederholungen, %3 s Pause</numerusform>
            <numerusform>%1: %n Serien mit %2 Wiederholungen, %3 s Pause</numerusform>
        </translation>
    </message>
    <message>
        <source>Today&apos;s exercises</source>
        <translation>Heutige Übungen</translation>
    </message>
    <message>
        <source>Hello, %1</source>
        <translation>Hallo, %1</translation>
    </message>
    <message>
        <source>Your therapist has not given you any exercises yet.</source>
        <translation>Ihre Therapeutin hat Ihnen noch keine Übungen gegeben.</translation>
    </message>
    <message>
        <source>Today&apos;s exercises:</source>
        <translation>Heutige Übungen:</translation>
    </message>
    <message>
        <source>(not measured without the camera)</source>
        <translation>(ohne Kamera nicht gemessen)</translation>
    </message>
    <message>
        <source>What can be measured</source>
        <translation>Was gemessen werden kann</translation>
    </message>
    <message>
        <source>This set-up has no camera. ArmTrack measures your elbow and forearm well with the two sensors alone. It cannot trust the shoulder&apos;s angles without the camera: they drift slowly about the vertical. Do the shoulder exercises as your therapist showed you; they are recorded for your therapist, but ArmTrack does not count them or show their numbers.%1</source>
        <translation>Diese Ausstattung hat keine Kamera. Ellbogen und Unterarm misst ArmTrack mit den beiden Sensoren allein gut. Den Winkeln der Schulter kann es ohne Kamera nicht trauen: Sie driften langsam um die Senkrechte. Machen Sie die Schulterübungen so, wie Ihre Therapeutin es Ihnen gezeigt hat; sie werden für sie aufgezeichnet, aber ArmTrack zählt sie nicht und zeigt keine Zahlen dazu.%1</translation>
    </message>
    <message>
        <source>None of today&apos;s exercises needs it.</source>
        <translation>Keine der heutigen Übungen braucht sie.</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation>&amp;Abmelden</translation>
    </message>
    <message>
        <source>I use the keyboard or the mouse</source>
        <translation>Ich benutze Tastatur oder Maus</translation>
    </message>
    <message>
        <source>I use one switch: the choices light up in turn</source>
        <translation>Ich benutze einen Taster: Die Auswahl leuchtet nacheinander auf</translation>
    </message>
    <message>
        <source>I use one switch: press to go on</source>
        <translation>Ich benutze einen Taster: Drücken heißt weiter</translation>
    </message>
    <message>
        <source>How I press: %1</source>
        <translation>Wie ich drücke: %1</translation>
    </message>
    <message>
        <source>Press to change how you use ArmTrack</source>
        <translation>Drücken, um zu ändern, wie Sie ArmTrack bedienen</translation>
    </message>
    <message>
        <source>C&amp;linic</source>
        <translation>&amp;Klinik</translation>
    </message>
    <message>
        <source>Connect to the clinic with its address and your therapist&apos;s code</source>
        <translation>Mit der Adresse der Klinik und dem Code aus der Therapie verbinden</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeStyle</name>
    <message>
        <source>information</source>
        <translation>Information</translation>
    </message>
    <message>
        <source>well done</source>
        <translation>gut gemacht</translation>
    </message>
    <message>
        <source>hint</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>problem</source>
        <translation>Problem</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeSummaryChart</name>
    <message>
        <source>Chart of the range reached</source>
        <translation>Diagramm des erreichten Bereichs</translation>
    </message>
    <message>
        <source>Last time</source>
        <translation>Letztes Mal</translation>
    </message>
    <message>
        <source>%1 sessions ago</source>
        <translation>vor %1 Sitzungen</translation>
    </message>
    <message>
        <source>%1 (not measured)</source>
        <translation>%1 (nicht gemessen)</translation>
    </message>
    <message>
        <source>Today</source>
        <translation>Heute</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Farthest angle reached (degrees)</source>
        <translation>Größter erreichter Winkel (Grad)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeSummaryScreen</name>
    <message>
        <source>%1: %L2 of %L3 repetitions</source>
        <translation>%1: %L2 von %L3 Wiederholungen</translation>
    </message>
    <message>
        <source>%1: %L2 of %L3 sets done (not measured without the camera)</source>
        <translation>%1: %L2 von %L3 Serien gemacht (ohne Kamera nicht gemessen)</translation>
    </message>
    <message>
        <source>you reached %L1°, the target is %L2°</source>
        <translation>Sie haben %L1° erreicht, das Ziel ist %L2°</translation>
    </message>
    <message>
        <source>last time %L1°</source>
        <translation>letztes Mal %L1°</translation>
    </message>
    <message>
        <source>stopped early</source>
        <translation>vorzeitig beendet</translation>
    </message>
    <message>
        <source>Saving…</source>
        <translation>Wird gespeichert …</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>Well done, %1!</source>
        <translation>Gut gemacht, %1!</translation>
    </message>
    <message>
        <source>How much pain did you have? 0 is none, 10 the worst.</source>
        <translation>Wie viel Schmerz hatten Sie? 0 ist keiner, 10 der schlimmste.</translation>
    </message>
    <message>
        <source>Anything to tell your therapist? (You may leave it empty.)</source>
        <translation>Möchten Sie Ihrer Therapeutin etwas sagen? (Sie können es leer lassen.)</translation>
    </message>
    <message>
        <source>Less pain</source>
        <translation>Weniger Schmerz</translation>
    </message>
    <message>
        <source>More pain</source>
        <translation>Mehr Schmerz</translation>
    </message>
    <message>
        <source>Pain score</source>
        <translation>Schmerzwert</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Angabe</translation>
    </message>
    <message>
        <source>Your comment</source>
        <translation>Ihr Kommentar</translation>
    </message>
    <message>
        <source>Saved</source>
        <translation>Gespeichert</translation>
    </message>
    <message>
        <source>&amp;Save and finish</source>
        <translation>&amp;Speichern und beenden</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>S&amp;chließen</translation>
    </message>
    <message>
        <source>Saved. Your therapist will see it. Thank you!</source>
        <translation>Gespeichert. Ihre Therapeutin wird es sehen. Danke!</translation>
    </message>
    <message>
        <source>It could not be saved: %1. Press Save to try again.</source>
        <translation>Es konnte nicht gespeichert werden: %1. Drücken Sie Speichern, um es noch einmal zu versuchen.</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) leaning too far</source>
        <translation>
            <numerusform>%n Wiederholung zu weit geneigt</numerusform>
            <numerusform>%n Wiederholungen zu weit geneigt</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeWindow</name>
    <message>
        <source>ArmTrack: my exercises</source>
        <translation>ArmTrack: meine Übungen</translation>
    </message>
    <message>
        <source>My exercises</source>
        <translation>Meine Übungen</translation>
    </message>
    <message>
        <source>Whose exercises</source>
        <translation>Wessen Übungen</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Sending to the clinic</source>
        <translation>Senden an die Klinik</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::SensorCheckScreen</name>
    <message>
        <source>&amp;Start the check</source>
        <translation>Prüfung &amp;starten</translation>
    </message>
    <message>
        <source>&amp;Go on</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <source>S&amp;kip the check</source>
        <translation>Prüfung übers&amp;pringen</translation>
    </message>
    <message>
        <source>The sensors could not be started: %1</source>
        <translation>Die Sensoren konnten nicht gestartet werden: %1</translation>
    </message>
    <message>
        <source>The check could not be recorded: %1</source>
        <translation>Die Prüfung konnte nicht aufgezeichnet werden: %1</translation>
    </message>
    <message>
        <source>no data came from the sensors</source>
        <translation>von den Sensoren kamen keine Daten</translation>
    </message>
    <message>
        <source>Sensor check</source>
        <translation>Sensorprüfung</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Anweisung</translation>
    </message>
    <message>
        <source>Result of the check</source>
        <translation>Ergebnis der Prüfung</translation>
    </message>
    <message>
        <source>&amp;Check again</source>
        <translation>&amp;Noch einmal prüfen</translation>
    </message>
    <message>
        <source>&amp;Go on anyway</source>
        <translation>&amp;Trotzdem weiter</translation>
    </message>
    <message>
        <source>S&amp;top the check</source>
        <translation>Prüfung a&amp;bbrechen</translation>
    </message>
    <message>
        <source>First, a check of the sensors</source>
        <translation>Zuerst eine Prüfung der Sensoren</translation>
    </message>
    <message>
        <source>Strap the upper-arm sensor on your upper arm and the forearm sensor on your forearm, each with its arrow pointing up towards your shoulder, as in the picture. Let your arm hang loosely straight down. After Start, keep still for 3 seconds, then bend your elbow up and straighten it again, three times.</source>
        <translation>Schnallen Sie den Oberarm-Sensor an den Oberarm und den Unterarm-Sensor an den Unterarm, jeweils mit dem Pfeil nach oben zur Schulter, wie im Bild. Lassen Sie den Arm locker gerade herunterhängen. Halten Sie nach Start 3 Sekunden still, dann beugen Sie den Ellbogen und strecken ihn wieder, dreimal.</translation>
    </message>
    <message>
        <source>Starting the sensors…</source>
        <translation>Sensoren werden gestartet …</translation>
    </message>
    <message>
        <source>Let your arm hang loosely straight down.</source>
        <translation>Lassen Sie den Arm locker gerade herunterhängen.</translation>
    </message>
    <message>
        <source>Keep still: %1</source>
        <translation>Stillhalten: %1</translation>
    </message>
    <message>
        <source>Let your arm hang loosely straight down, and keep it still.</source>
        <translation>Lassen Sie den Arm locker gerade herunterhängen und halten Sie ihn still.</translation>
    </message>
    <message>
        <source>Bend your elbow: %1 of %2</source>
        <translation>Ellbogen beugen: %1 von %2</translation>
    </message>
    <message>
        <source>Bend your elbow up as far as is comfortable, then straighten it again. Keep your upper arm still.</source>
        <translation>Beugen Sie den Ellbogen so weit, wie es angenehm ist, und strecken Sie ihn wieder. Halten Sie den Oberarm ruhig.</translation>
    </message>
    <message>
        <source>Keep still</source>
        <translation>Stillhalten</translation>
    </message>
    <message>
        <source>Let your arm hang down again.</source>
        <translation>Lassen Sie den Arm wieder herunterhängen.</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>Wird geprüft …</translation>
    </message>
    <message>
        <source>You can relax your arm.</source>
        <translation>Sie können den Arm entspannen.</translation>
    </message>
    <message>
        <source>The sensors are right</source>
        <translation>Die Sensoren sitzen richtig</translation>
    </message>
    <message>
        <source>Both sensors are on the right places and the right way round.</source>
        <translation>Beide Sensoren sind an der richtigen Stelle und richtig herum.</translation>
    </message>
    <message>
        <source>Well done.</source>
        <translation>Gut gemacht.</translation>
    </message>
    <message>
        <source>Please change the sensors</source>
        <translation>Bitte ändern Sie die Sensoren</translation>
    </message>
    <message>
        <source>Please do the check again</source>
        <translation>Bitte machen Sie die Prüfung noch einmal</translation>
    </message>
    <message>
        <source>Change them as in the picture, then press Check again.</source>
        <translation>Ändern Sie sie wie im Bild und drücken Sie dann Noch einmal prüfen.</translation>
    </message>
    <message>
        <source>Press Check again when you are ready.</source>
        <translation>Drücken Sie Noch einmal prüfen, wenn Sie bereit sind.</translation>
    </message>
    <message>
        <source>No data came from the upper-arm sensor. Check that it is switched on and charged, then press Check again.</source>
        <translation>Vom Oberarm-Sensor kamen keine Daten. Prüfen Sie, ob er eingeschaltet und geladen ist, und drücken Sie dann Noch einmal prüfen.</translation>
    </message>
    <message>
        <source>No data came from the forearm sensor. Check that it is switched on and charged, then press Check again.</source>
        <translation>Vom Unterarm-Sensor kamen keine Daten. Prüfen Sie, ob er eingeschaltet und geladen ist, und drücken Sie dann Noch einmal prüfen.</translation>
    </message>
    <message>
        <source>Your arm was not still at the start. Let it hang loosely and keep it still until the countdown ends.</source>
        <translation>Ihr Arm war am Anfang nicht still. Lassen Sie ihn locker hängen und halten Sie ihn still, bis der Countdown endet.</translation>
    </message>
    <message>
        <source>ArmTrack did not see your elbow bend. When asked, bend your elbow up and straighten it again, three times.</source>
        <translation>ArmTrack hat Ihren Ellbogen nicht beugen sehen. Beugen Sie ihn auf Aufforderung und strecken Sie ihn wieder, dreimal.</translation>
    </message>
    <message>
        <source>Both sensors moved the same way. Keep your upper arm still while you bend the elbow, and check that one sensor is on the upper arm and one on the forearm.</source>
        <translation>Beide Sensoren haben sich gleich bewegt. Halten Sie den Oberarm ruhig, während Sie den Ellbogen beugen, und prüfen Sie, dass ein Sensor am Oberarm und einer am Unterarm sitzt.</translation>
    </message>
    <message>
        <source>A sensor gives readings that do not make sense. Switch it off and on again; if this happens again, call your therapist.</source>
        <translation>Ein Sensor liefert unsinnige Werte. Schalten Sie ihn aus und wieder ein; wenn das wieder passiert, rufen Sie Ihre Therapeutin an.</translation>
    </message>
    <message>
        <source>The two sensors are swapped: the upper-arm sensor is on your forearm, and the forearm sensor is on your upper arm. Put each one on the other&apos;s place.</source>
        <translation>Die beiden Sensoren sind vertauscht: Der Oberarm-Sensor sitzt an Ihrem Unterarm und der Unterarm-Sensor an Ihrem Oberarm. Setzen Sie jeden an die Stelle des anderen.</translation>
    </message>
    <message>
        <source>The sensor on your upper arm is upside down: its arrow points down. Turn it round so that the arrow points up towards your shoulder.</source>
        <translation>Der Sensor an Ihrem Oberarm steht auf dem Kopf: Sein Pfeil zeigt nach unten. Drehen Sie ihn um, sodass der Pfeil nach oben zur Schulter zeigt.</translation>
    </message>
    <message>
        <source>The sensor on your forearm is upside down: its arrow points down. Turn it round so that the arrow points up towards your shoulder.</source>
        <translation>Der Sensor an Ihrem Unterarm steht auf dem Kopf: Sein Pfeil zeigt nach unten. Drehen Sie ihn um, sodass der Pfeil nach oben zur Schulter zeigt.</translation>
    </message>
    <message>
        <source>The sensor on your upper arm sits crooked, or your arm was not hanging straight. Straighten the strap and let your arm hang loosely.</source>
        <translation>Der Sensor an Ihrem Oberarm sitzt schief, oder Ihr Arm hing nicht gerade. Richten Sie das Band gerade und lassen Sie den Arm locker hängen.</translation>
    </message>
    <message>
        <source>The sensor on your forearm sits crooked, or your elbow was not straight. Straighten the strap and let your arm hang loosely.</source>
        <translation>Der Sensor an Ihrem Unterarm sitzt schief, oder Ihr Ellbogen war nicht gestreckt. Richten Sie das Band gerade und lassen Sie den Arm locker hängen.</translation>
    </message>
    <message>
        <source>Sit upright with your back against the chair, let your arm hang loosely straight down, and keep still.</source>
        <translation>Setzen Sie sich aufrecht mit dem Rücken an die Stuhllehne, lassen Sie den Arm locker gerade nach unten hängen und halten Sie still.</translation>
    </message>
    <message>
        <source>All three sensors are on the right places and the right way round.</source>
        <translation>Alle drei Sensoren sitzen an der richtigen Stelle und richtig herum.</translation>
    </message>
    <message>
        <source>No data came from the chest sensor. Check that it is switched on and charged, then press Check again.</source>
        <translation>Vom Brustsensor kamen keine Daten. Prüfen Sie, ob er eingeschaltet und geladen ist, und drücken Sie dann „Erneut prüfen“.</translation>
    </message>
    <message>
        <source>The chest sensor seems to be on upside down. Turn it the other way up, as your therapist showed you, and sit upright.</source>
        <translation>Der Brustsensor scheint verkehrt herum zu sitzen. Drehen Sie ihn um, so wie Ihre Therapeutin oder Ihr Therapeut es gezeigt hat, und setzen Sie sich aufrecht.</translation>
    </message>
    <message>
        <source>The chest sensor seems to be turned: it sits %1° off. Put it flat on the middle of your breastbone, the way your therapist showed you, and sit upright.</source>
        <translation>Der Brustsensor scheint verdreht zu sein: Er sitzt %1° schief. Legen Sie ihn flach auf die Mitte des Brustbeins, so wie Ihre Therapeutin oder Ihr Therapeut es gezeigt hat, und setzen Sie sich aufrecht.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::StrapPicture</name>
    <message>
        <source>How it should be</source>
        <translation>So soll es sein</translation>
    </message>
    <message>
        <source>upper-arm sensor</source>
        <translation>Oberarm-Sensor</translation>
    </message>
    <message>
        <source>forearm sensor</source>
        <translation>Unterarm-Sensor</translation>
    </message>
    <message>
        <source>The upper-arm sensor on the upper arm and the forearm sensor on the forearm, both with their arrow pointing up towards the shoulder.</source>
        <translation>Der Oberarm-Sensor am Oberarm und der Unterarm-Sensor am Unterarm, beide mit dem Pfeil nach oben zur Schulter.</translation>
    </message>
    <message>
        <source>Now the two sensors are on each other&apos;s place.</source>
        <translation>Jetzt sitzen die beiden Sensoren jeweils an der Stelle des anderen.</translation>
    </message>
    <message>
        <source>Now the sensor on the upper arm has its arrow pointing down.</source>
        <translation>Jetzt zeigt der Pfeil des Sensors am Oberarm nach unten.</translation>
    </message>
    <message>
        <source>Now the sensor on the forearm has its arrow pointing down.</source>
        <translation>Jetzt zeigt der Pfeil des Sensors am Unterarm nach unten.</translation>
    </message>
    <message>
        <source>Now the sensor on the upper arm sits crooked.</source>
        <translation>Jetzt sitzt der Sensor am Oberarm schief.</translation>
    </message>
    <message>
        <source>Now the sensor on the forearm sits crooked.</source>
        <translation>Jetzt sitzt der Sensor am Unterarm schief.</translation>
    </message>
    <message>
        <source>Picture of the sensors on the arm</source>
        <translation>Bild der Sensoren am Arm</translation>
    </message>
    <message>
        <source>Worn correctly on your left arm</source>
        <translation>Richtig angelegt an Ihrem linken Arm</translation>
    </message>
    <message>
        <source>Worn correctly on your right arm</source>
        <translation>Richtig angelegt an Ihrem rechten Arm</translation>
    </message>
    <message>
        <source>Now, on your left arm</source>
        <translation>Jetzt, an Ihrem linken Arm</translation>
    </message>
    <message>
        <source>Now, on your right arm</source>
        <translation>Jetzt, an Ihrem rechten Arm</translation>
    </message>
    <message>
        <source>Your left arm, seen from the side.</source>
        <translation>Ihr linker Arm, von der Seite gesehen.</translation>
    </message>
    <message>
        <source>Your right arm, seen from the side.</source>
        <translation>Ihr rechter Arm, von der Seite gesehen.</translation>
    </message>
</context>
<context>
    <name>armtrack::reports</name>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <source>numbers: repetitions at their peaks (p = partial)</source>
        <translation>Zahlen: Wiederholungen an ihren Scheitelpunkten (t = teilweise)</translation>
    </message>
    <message>
        <source>angle (deg)</source>
        <translation>Winkel (°)</translation>
    </message>
    <message>
        <source>date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>not measured in this period</source>
        <translation>in diesem Zeitraum nicht gemessen</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <source>Page %1</source>
        <translation>Seite %1</translation>
    </message>
    <message>
        <source>Progress report</source>
        <translation>Verlaufsbericht</translation>
    </message>
    <message>
        <source>Patient and period</source>
        <translation>Patient und Zeitraum</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Patient code</source>
        <translation>Patientenkennung</translation>
    </message>
    <message>
        <source>Date of birth</source>
        <translation>Geburtsdatum</translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation>Betroffene Seite</translation>
    </message>
    <message>
        <source>Therapist</source>
        <translation>Therapeut</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sitzungen</translation>
    </message>
    <message>
        <source>Range of motion over time</source>
        <translation>Bewegungsausmaß im Verlauf</translation>
    </message>
    <message>
        <source>%1: largest angle reached (deg)</source>
        <translation>%1: größter erreichter Winkel (°)</translation>
    </message>
    <message>
        <source>Normal ranges: %1.</source>
        <translation>Normbereiche: %1.</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>Reps</source>
        <translation>Wdh.</translation>
    </message>
    <message>
        <source>%1 ROM</source>
        <translation>%1 ROM</translation>
    </message>
    <message>
        <source>ROM in degrees (maximum minus minimum over the session).</source>
        <translation>ROM in Grad (Maximum minus Minimum über die Sitzung).</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>%1 (%2), progress %3</source>
        <translation>%1 (%2), Verlauf %3</translation>
    </message>
    <message>
        <source>progress report</source>
        <translation>Verlaufsbericht</translation>
    </message>
    <message>
        <source>Progress report: %1, %2</source>
        <translation>Verlaufsbericht: %1, %2</translation>
    </message>
    <message>
        <source>Shoulder flexion</source>
        <translation>Schulterflexion</translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation>Schulterabduktion</translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation>Schulterinnenrotation</translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation>Ellenbogenflexion</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation>Pronation/Supination</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>both</source>
        <translation>beide</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>either</source>
        <translation>beliebig</translation>
    </message>
    <message>
        <source>female</source>
        <translation>weiblich</translation>
    </message>
    <message>
        <source>male</source>
        <translation>männlich</translation>
    </message>
    <message>
        <source>diverse</source>
        <translation>divers</translation>
    </message>
    <message>
        <source>complete</source>
        <translation>vollständig</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>unterbrochen</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>läuft</translation>
    </message>
    <message>
        <source>%1 %2 UTC</source>
        <comment>a date and a time of day</comment>
        <translation>%1, %2 UTC</translation>
    </message>
    <message>
        <source>%1 - %2 - generated %3</source>
        <translation>%1 – %2 – erstellt am %3</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>(not valid JSON: %1 at offset %2)</source>
        <translation>(kein gültiges JSON: %1 bei Position %2)</translation>
    </message>
    <message numerus="yes">
        <source>... %n more</source>
        <translation>
            <numerusform>... %n weitere</numerusform>
            <numerusform>... %n weitere</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %2, target %3 to %4 deg, %n repetitions</source>
        <translation>
            <numerusform>%1: %2, Ziel %3 bis %4°, %n Wiederholung</numerusform>
            <numerusform>%1: %2, Ziel %3 bis %4°, %n Wiederholungen</numerusform>
        </translation>
    </message>
    <message>
        <source>Patient and session</source>
        <translation>Patient und Sitzung</translation>
    </message>
    <message>
        <source>Sex</source>
        <translation>Geschlecht</translation>
    </message>
    <message>
        <source>Side measured</source>
        <translation>Gemessene Seite</translation>
    </message>
    <message>
        <source>Session</source>
        <translation>Sitzung</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnose</translation>
    </message>
    <message>
        <source>Devices and calibration</source>
        <translation>Geräte und Kalibrierung</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <source>No devices were recorded for this session.</source>
        <translation>Für diese Sitzung wurden keine Geräte gespeichert.</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <source>%1 not defined</source>
        <translation>%1 nicht definiert</translation>
    </message>
    <message>
        <source>Metrics per clinical angle</source>
        <translation>Kennwerte je klinischem Winkel</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Min (deg)</source>
        <translation>Min. (°)</translation>
    </message>
    <message>
        <source>Max (deg)</source>
        <translation>Max. (°)</translation>
    </message>
    <message>
        <source>ROM (deg)</source>
        <translation>ROM (°)</translation>
    </message>
    <message>
        <source>Peak velocity (deg/s)</source>
        <translation>Spitzengeschwindigkeit (°/s)</translation>
    </message>
    <message>
        <source>Mean velocity (deg/s)</source>
        <translation>Mittlere Geschwindigkeit (°/s)</translation>
    </message>
    <message>
        <source>Moving time (s)</source>
        <translation>Bewegungszeit (s)</translation>
    </message>
    <message>
        <source>Joint angles over time</source>
        <translation>Gelenkwinkel im Zeitverlauf</translation>
    </message>
    <message>
        <source>shaded: protocol target %1 to %2 deg</source>
        <translation>schattiert: Ziel des Protokolls %1 bis %2°</translation>
    </message>
    <message>
        <source>%1 (deg)</source>
        <translation>%1 (°)</translation>
    </message>
    <message>
        <source>p</source>
        <comment>a partial repetition&apos;s mark on the plot</comment>
        <translation>t</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>No repetitions were detected (0 repetitions).</source>
        <translation>Es wurden keine Wiederholungen erkannt (0 Wiederholungen).</translation>
    </message>
    <message numerus="yes">
        <source>%n repetitions counted on %1: %2 full, %3 partial (judged against a reference range of %4 deg); %5 cut by the start or end of the recording and not counted.</source>
        <translation>
            <numerusform>%n Wiederholung bei %1 gezählt: %2 vollständig, %3 teilweise (beurteilt an einem Referenzbereich von %4°); %5 vom Beginn oder Ende der Aufnahme abgeschnitten und nicht gezählt.</numerusform>
            <numerusform>%n Wiederholungen bei %1 gezählt: %2 vollständig, %3 teilweise (beurteilt an einem Referenzbereich von %4°); %5 vom Beginn oder Ende der Aufnahme abgeschnitten und nicht gezählt.</numerusform>
        </translation>
    </message>
    <message>
        <source>#</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>Beginn (s)</translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation>Ende (s)</translation>
    </message>
    <message>
        <source>ROM of %1 (deg)</source>
        <translation>ROM %1 (°)</translation>
    </message>
    <message>
        <source>Partial</source>
        <translation>Teilweise</translation>
    </message>
    <message>
        <source>Comparison with normative ranges</source>
        <translation>Vergleich mit Normbereichen</translation>
    </message>
    <message>
        <source>Comparison with earlier sessions</source>
        <translation>Vergleich mit früheren Sitzungen</translation>
    </message>
    <message>
        <source>Range of motion (deg) of each angle per session.</source>
        <translation>Bewegungsausmaß (°) jedes Winkels je Sitzung.</translation>
    </message>
    <message>
        <source>%1 this session</source>
        <translation>%1 diese Sitzung</translation>
    </message>
    <message>
        <source>Change since last</source>
        <translation>Veränderung seit der letzten</translation>
    </message>
    <message>
        <source>Other side, %1</source>
        <translation>Andere Seite, %1</translation>
    </message>
    <message>
        <source>No earlier sessions to compare with.</source>
        <translation>Keine früheren Sitzungen zum Vergleich.</translation>
    </message>
    <message>
        <source>Therapist&apos;s notes</source>
        <translation>Notizen des Therapeuten</translation>
    </message>
    <message>
        <source>No notes.</source>
        <translation>Keine Notizen.</translation>
    </message>
    <message>
        <source>%1 (%2), session of %3</source>
        <translation>%1 (%2), Sitzung vom %3</translation>
    </message>
    <message>
        <source>session report</source>
        <translation>Sitzungsbericht</translation>
    </message>
    <message>
        <source>Session report: %1, %2</source>
        <translation>Sitzungsbericht: %1, %2</translation>
    </message>
    <message>
        <source>Session report</source>
        <translation>Sitzungsbericht</translation>
    </message>
    <message>
        <source>shaded: AAOS normal range of motion, 0-%1 deg</source>
        <translation>schattiert: normales Bewegungsausmaß nach AAOS, 0–%1°</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 samples used, %2 rows rejected (not finite), %3 gaps. Smoothness of the wrist path: %4, %5.</source>
        <translation>%1 Messwerte verwendet, %2 Zeilen verworfen (nicht endlich), %3 Lücken. Glattheit der Handgelenksbahn: %4, %5.</translation>
    </message>
    <message>
        <source>females aged %1-%2</source>
        <translation>Frauen im Alter von %1-%2 Jahren</translation>
    </message>
    <message>
        <source>males aged %1-%2</source>
        <translation>Männer im Alter von %1-%2 Jahren</translation>
    </message>
    <message>
        <source>%1 (maximum); %2 (minimum)</source>
        <translation>%1 (Maximum); %2 (Minimum)</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: the date of birth is not recorded.</source>
        <translation>Referenzwerte nach Alter und Geschlecht (Soucie et al. 2011) werden nicht verwendet: Das Geburtsdatum ist nicht erfasst.</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: the patient was %1 on the day of the session, outside the study&apos;s 2 to 69 years.</source>
        <translation>Referenzwerte nach Alter und Geschlecht (Soucie et al. 2011) werden nicht verwendet: Der Patient war am Tag der Sitzung %1 Jahre alt, außerhalb der 2 bis 69 Jahre der Studie.</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: the patient&apos;s sex is not recorded as female or male.</source>
        <translation>Referenzwerte nach Alter und Geschlecht (Soucie et al. 2011) werden nicht verwendet: Das Geschlecht des Patienten ist nicht als weiblich oder männlich erfasst.</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: this version has none for %1.</source>
        <translation>Referenzwerte nach Alter und Geschlecht (Soucie et al. 2011) werden nicht verwendet: Diese Version enthält keine für %1.</translation>
    </message>
    <message>
        <source>Normal range (deg)</source>
        <translation>Normbereich (Grad)</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Soucie et al. give the mean passive range of motion of healthy %1; the patient was %2 on the day of the session.</source>
        <translation>Soucie et al. geben das mittlere passive Bewegungsausmaß gesunder %1 an; der Patient war am Tag der Sitzung %2 Jahre alt.</translation>
    </message>
    <message>
        <source>Shoulder extension</source>
        <translation>Schulterextension</translation>
    </message>
    <message>
        <source>Shoulder external rotation</source>
        <translation>Schulteraußenrotation</translation>
    </message>
    <message>
        <source>Forearm supination</source>
        <translation>Unterarmsupination</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <comment>the motion, beside the supination chart</comment>
        <translation>Unterarmpronation</translation>
    </message>
    <message>
        <source>no sessions</source>
        <translation>keine Sitzungen</translation>
    </message>
    <message>
        <source>until %1</source>
        <translation>bis %1</translation>
    </message>
    <message>
        <source>from %1</source>
        <translation>ab %1</translation>
    </message>
    <message>
        <source>Period</source>
        <translation>Zeitraum</translation>
    </message>
    <message>
        <source>No sessions in the period (%1).</source>
        <translation>Keine Sitzungen im Zeitraum (%1).</translation>
    </message>
    <message>
        <source>; latest %1 % of normal</source>
        <translation>; zuletzt %1 % der Norm</translation>
    </message>
    <message>
        <source>%1 of %2 deg, %3 %</source>
        <comment>the largest angle, its normal, the percent of normal</comment>
        <translation>%1 von %2°, %3 %</translation>
    </message>
    <message>
        <source>Grey: the normal range of motion; blue: this session&apos;s range (negative = extension, external rotation, supination). Shoulder adduction has no normal limit in the sources; its range is shown from 0. Beside each bar: the largest angle reached in the motion the angle is named after (flexion, abduction, internal rotation, elbow flexion, pronation), that motion&apos;s normal range, and the first as a percentage of the second, as on the patient&apos;s page. Sources: %1.</source>
        <translation>Grau: das normale Bewegungsausmaß; blau: das Bewegungsausmaß dieser Sitzung (negativ = Extension, Außenrotation, Supination). Für die Schulteradduktion nennen die Quellen keinen Normwert; ihr Bereich wird ab 0 gezeigt. Neben jedem Balken: der größte erreichte Winkel in der Bewegung, nach der der Winkel benannt ist (Flexion, Abduktion, Innenrotation, Ellbogenflexion, Pronation), der Normbereich dieser Bewegung und der erste in Prozent des zweiten, wie auf der Patientenseite. Quellen: %1.</translation>
    </message>
    <message>
        <source>Events marked (time since the recording began, as in the review): %1</source>
        <translation>Markierte Ereignisse (Zeit seit Beginn der Aufnahme, wie in der Auswertung): %1</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <source>%1 deg</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>Good</source>
        <translation>Gut</translation>
    </message>
    <message>
        <source>Usable</source>
        <translation>Brauchbar</translation>
    </message>
    <message>
        <source>Poor</source>
        <translation>Schlecht</translation>
    </message>
    <message>
        <source>Sensor calibration: %1.</source>
        <translation>Sensorkalibrierung: %1.</translation>
    </message>
    <message>
        <source>Sensor calibration: %1</source>
        <translation>Sensorkalibrierung: %1</translation>
    </message>
    <message>
        <source>Sensor calibration: %1. %2</source>
        <translation>Sensorkalibrierung: %1. %2</translation>
    </message>
    <message>
        <source>Sensor calibration: none was made for this session; the lengths below are the ones the session was recorded with (measured or default).</source>
        <translation>Sensorkalibrierung: für diese Sitzung wurde keine durchgeführt; die folgenden Längen sind die, mit denen die Sitzung aufgenommen wurde (gemessen oder Standardwerte).</translation>
    </message>
    <message>
        <source>Segments: upper arm %1 (shoulder to elbow), forearm %2 (elbow to wrist).</source>
        <translation>Segmente: Oberarm %1 (Schulter bis Ellbogen), Unterarm %2 (Ellbogen bis Handgelenk).</translation>
    </message>
    <message>
        <source>%1 from the %2, mounted at %3 about the segment, %4 off its axis</source>
        <translation>%1 von %2 entfernt, um %3 um das Segment gedreht angebracht, %4 neben seiner Achse</translation>
    </message>
    <message>
        <source>shoulder</source>
        <translation>der Schulter</translation>
    </message>
    <message>
        <source>Upper-arm sensor: %1.</source>
        <translation>Oberarmsensor: %1.</translation>
    </message>
    <message>
        <source>elbow</source>
        <translation>dem Ellbogen</translation>
    </message>
    <message>
        <source>Forearm sensor: %1.</source>
        <translation>Unterarmsensor: %1.</translation>
    </message>
    <message>
        <source>Arm: %1.</source>
        <translation>Arm: %1.</translation>
    </message>
    <message>
        <source>Camera: calibrated, %1 m from the shoulder.</source>
        <translation>Kamera: kalibriert, %1 m von der Schulter entfernt.</translation>
    </message>
    <message>
        <source>Camera: calibrated.</source>
        <translation>Kamera: kalibriert.</translation>
    </message>
    <message>
        <source>Trunk compensation</source>
        <translation>Rumpfkompensation</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>Not measured: the session had no sternum sensor (trunk IMU) and no optical shoulder position.</source>
        <translation>Nicht gemessen: Die Sitzung hatte keinen Brustbeinsensor (Rumpf-IMU) und keine optisch erfasste Schulterposition.</translation>
    </message>
    <message>
        <source>The largest trunk flexion (forward lean), lateral bending and axial rotation from the upright start pose, and the largest displacement of the shoulder, over the session and in each repetition.</source>
        <translation>Die größte Rumpfflexion (Vorneigung), Seitneigung und Rumpfrotation gegenüber der aufrechten Ausgangsstellung und die größte Verschiebung der Schulter, über die Sitzung und in jeder Wiederholung.</translation>
    </message>
    <message>
        <source>Trunk flexion</source>
        <translation>Rumpfflexion</translation>
    </message>
    <message>
        <source>Lateral bending</source>
        <translation>Seitneigung</translation>
    </message>
    <message>
        <source>Axial rotation</source>
        <translation>Rumpfrotation</translation>
    </message>
    <message>
        <source>Shoulder displacement</source>
        <translation>Schulterverschiebung</translation>
    </message>
    <message>
        <source>%1 of %2 repetitions were made with trunk compensation (trunk flexion over %3 deg).</source>
        <translation>%1 von %2 Wiederholungen wurden mit Rumpfkompensation ausgeführt (Rumpfflexion über %3°).</translation>
    </message>
    <message>
        <source>Per repetition</source>
        <translation>Je Wiederholung</translation>
    </message>
    <message>
        <source>Trunk flexion (deg)</source>
        <translation>Rumpfflexion (°)</translation>
    </message>
    <message>
        <source>Lateral bending (deg)</source>
        <translation>Seitneigung (°)</translation>
    </message>
    <message>
        <source>Axial rotation (deg)</source>
        <translation>Rumpfrotation (°)</translation>
    </message>
    <message>
        <source>Shoulder (cm)</source>
        <translation>Schulter (cm)</translation>
    </message>
    <message>
        <source>Compensated</source>
        <translation>Kompensiert</translation>
    </message>
    <message>
        <source>Trunk compensation: largest trunk flexion (deg)</source>
        <translation>Rumpfkompensation: größte Rumpfflexion (°)</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleChart</name>
    <message>
        <source>Plot of %1 over time in degrees; the table beside it holds the same numbers</source>
        <translation>Verlauf von %1 in Grad; die Tabelle daneben enthält dieselben Zahlen</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Compared session</source>
        <translation>Vergleichssitzung</translation>
    </message>
    <message>
        <source>%1 (°)</source>
        <translation>%1 (°)</translation>
    </message>
    <message>
        <source>likely range</source>
        <translation>wahrscheinlicher Bereich</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AnglePlotPanel</name>
    <message>
        <source>Joint angle plots</source>
        <translation>Gelenkwinkel-Diagramme</translation>
    </message>
    <message>
        <source>Joint angles table</source>
        <translation>Tabelle der Gelenkwinkel</translation>
    </message>
    <message>
        <source>The current value of each angle, its uncertainty, the range over the plotted time and the target</source>
        <translation>Der aktuelle Wert jedes Winkels, seine Unsicherheit, der Bereich über die gezeigte Zeit und das Ziel</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleReadouts</name>
    <message>
        <source>Current joint angles</source>
        <translation>Aktuelle Gelenkwinkel</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>The angle lies within this range of the value shown, with about 95 % probability.</source>
        <translation>Der Winkel liegt mit etwa 95 % Wahrscheinlichkeit in diesem Bereich um den gezeigten Wert.</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleTableModel</name>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Now</source>
        <translation>Jetzt</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min.</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Confidence</source>
        <translation>Genauigkeit</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::Angles</name>
    <message>
        <source>Shoulder flexion</source>
        <translation>Schulterflexion</translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation>Schulterabduktion</translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation>Schulterinnenrotation</translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation>Ellenbogenflexion</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation>Pronation/Supination</translation>
    </message>
    <message>
        <source>sensor lost</source>
        <translation>Sensor verloren</translation>
    </message>
    <message>
        <source>heading</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>heading from the start pose</source>
        <translation>Richtung nur aus der Anfangshaltung</translation>
    </message>
    <message>
        <source>uncertain</source>
        <translation>unsicher</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::ArmView</name>
    <message>
        <source>3D view of the arm</source>
        <translation>3D-Ansicht des Arms</translation>
    </message>
    <message>
        <source>The estimated arm with its sensors. Arrow keys turn the view, plus and minus zoom, Home resets the view.</source>
        <translation>Der berechnete Arm mit seinen Sensoren. Pfeiltasten drehen die Ansicht, Plus und Minus zoomen, Pos1 setzt die Ansicht zurück.</translation>
    </message>
    <message>
        <source>Drag to turn the view, scroll to zoom; Home resets it</source>
        <translation>Ziehen dreht die Ansicht, Scrollen zoomt; Pos1 setzt sie zurück</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Ansicht zurücksetzen</translation>
    </message>
    <message>
        <source>Left arm</source>
        <translation>Linker Arm</translation>
    </message>
    <message>
        <source>Right arm</source>
        <translation>Rechter Arm</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceHealthModel</name>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Stream</source>
        <translation>Datenstrom</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>Rate</translation>
    </message>
    <message>
        <source>Lost</source>
        <translation>Verloren</translation>
    </message>
    <message>
        <source>Rejected</source>
        <translation>Verworfen</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>down</source>
        <translation>ausgefallen</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>inaktiv</translation>
    </message>
    <message>
        <source>%L1 Hz</source>
        <translation>%L1 Hz</translation>
    </message>
    <message>
        <source>Battery low: charge the device after the session</source>
        <translation>Akku schwach: Gerät nach der Sitzung laden</translation>
    </message>
    <message>
        <source>The device does not report its battery</source>
        <translation>Das Gerät meldet seinen Akkustand nicht</translation>
    </message>
    <message>
        <source>not reported</source>
        <translation>nicht gemeldet</translation>
    </message>
    <message>
        <source>%L1 %, low</source>
        <translation>%L1 %, schwach</translation>
    </message>
    <message>
        <source>%L1 %</source>
        <translation>%L1 %</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Akku</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceHealthPanel</name>
    <message>
        <source>Device health</source>
        <translation>Gerätezustand</translation>
    </message>
    <message>
        <source>Device health summary</source>
        <translation>Zusammenfassung des Gerätezustands</translation>
    </message>
    <message>
        <source>Devices and streams</source>
        <translation>Geräte und Datenströme</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceOptionsForm</name>
    <message>
        <source>Device options</source>
        <translation>Geräteoptionen</translation>
    </message>
    <message>
        <source>(not set)</source>
        <translation>(nicht gesetzt)</translation>
    </message>
    <message>
        <source>Ports found...</source>
        <translation>Gefundene Anschlüsse...</translation>
    </message>
    <message>
        <source>Serial ports found on this computer</source>
        <translation>Auf diesem Computer gefundene serielle Anschlüsse</translation>
    </message>
    <message>
        <source>No serial port found: plug the sensor&apos;s receiver in (or pair the Bluetooth sensor), then look again</source>
        <translation>Kein serieller Anschluss gefunden: den Empfänger des Sensors einstecken (oder den Bluetooth-Sensor koppeln), dann erneut nachsehen</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceWords</name>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbindet</translation>
    </message>
    <message>
        <source>streaming</source>
        <translation>sendet</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>simulated IMUs, Kinect and webcam in real time, with fault injection</source>
        <translation>simulierte IMUs, Kinect und Webcam in Echtzeit, mit eingespielten Fehlern</translation>
    </message>
    <message>
        <source>Kinect v1 (libfreenect): elbow and wrist markers in 3D, shoulder frame</source>
        <translation>Kinect v1 (libfreenect): Ellenbogen- und Handgelenkmarker in 3D, im Schulter-Koordinatensystem</translation>
    </message>
    <message>
        <source>do-it-yourself IMU (ESP32/Arduino) sending ArmTrack&apos;s $IMU text lines over a serial port or UDP</source>
        <translation>selbstgebaute IMU (ESP32/Arduino), die ArmTracks $IMU-Textzeilen über eine serielle Schnittstelle oder UDP sendet</translation>
    </message>
    <message>
        <source>x-io NGIMU over Wi-Fi (OSC over UDP, /sensors messages)</source>
        <translation>x-io NGIMU über WLAN (OSC über UDP, /sensors-Nachrichten)</translation>
    </message>
    <message>
        <source>Shimmer3 IMU (LogAndStream firmware) over its Bluetooth serial port</source>
        <translation>Shimmer3-IMU (Firmware LogAndStream) über ihre serielle Bluetooth-Schnittstelle</translation>
    </message>
    <message>
        <source>elbow and wrist positions from an external body tracker (Kinect SDK, pose estimator), JSON over UDP</source>
        <translation>Ellenbogen- und Handgelenkpositionen von einem externen Körper-Tracker (Kinect SDK, Posenschätzer), JSON über UDP</translation>
    </message>
    <message>
        <source>wrist and elbow marker pixels from a camera or a video file (OpenCV)</source>
        <translation>Pixel der Handgelenk- und Ellenbogenmarker aus einer Kamera oder einer Videodatei (OpenCV)</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::HealthTracker</name>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>error: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>verbindet neu</translation>
    </message>
    <message>
        <source>reconnecting: %1</source>
        <translation>verbindet neu: %1</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbindet</translation>
    </message>
    <message>
        <source>no data for %L1 s</source>
        <translation>seit %L1 s keine Daten</translation>
    </message>
    <message>
        <source>waiting for data</source>
        <translation>wartet auf Daten</translation>
    </message>
    <message>
        <source>streaming, losing samples</source>
        <translation>sendet, verliert Messwerte</translation>
    </message>
    <message>
        <source>streaming</source>
        <translation>sendet</translation>
    </message>
    <message>
        <source>No devices</source>
        <translation>Keine Geräte</translation>
    </message>
    <message>
        <source>All devices are streaming</source>
        <translation>Alle Geräte senden</translation>
    </message>
    <message>
        <source>Trunk (sternum) sensor</source>
        <translation>Rumpfsensor (Brustbein)</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::RepetitionCounterWidget</name>
    <message>
        <source>Repetitions</source>
        <translation>Wiederholungen</translation>
    </message>
    <message>
        <source>Repetitions done of the target</source>
        <translation>Erledigte Wiederholungen vom Ziel</translation>
    </message>
    <message>
        <source>Repetitions (%1)</source>
        <translation>Wiederholungen (%1)</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message numerus="yes">
        <source>%n partial</source>
        <translation>
            <numerusform>%n teilweise</numerusform>
            <numerusform>%n teilweise</numerusform>
        </translation>
    </message>
    <message>
        <source>moving</source>
        <translation>in Bewegung</translation>
    </message>
    <message>
        <source>target reached</source>
        <translation>Ziel erreicht</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::TrunkChart</name>
    <message>
        <source>Trunk flexion</source>
        <translation>Rumpfbeugung</translation>
    </message>
    <message>
        <source>Trunk lateral bending</source>
        <translation>Rumpfseitneigung</translation>
    </message>
    <message>
        <source>Trunk axial rotation</source>
        <translation>Rumpfrotation</translation>
    </message>
    <message>
        <source>Trunk</source>
        <translation>Rumpf</translation>
    </message>
    <message>
        <source>%1 (°)</source>
        <translation>%1 (°)</translation>
    </message>
    <message>
        <source>Trunk plot</source>
        <translation>Rumpfdiagramm</translation>
    </message>
    <message>
        <source>Trunk flexion, lateral bending and axial rotation over time in degrees, relative to the start pose</source>
        <translation>Rumpfbeugung, Seitneigung und Rotation im Zeitverlauf in Grad, bezogen auf die Ausgangshaltung</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::VtkBridge</name>
    <message>
        <source>OpenGL is not available, so the 3D view cannot be shown.</source>
        <translation>OpenGL ist nicht verfügbar, daher kann die 3D-Ansicht nicht gezeigt werden.</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.2; this display offers %1.%2.</source>
        <translation>Die 3D-Ansicht braucht OpenGL 3.2; diese Anzeige bietet %1.%2.</translation>
    </message>
</context>
</TS>
