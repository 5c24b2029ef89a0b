<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es" sourcelanguage="en">
<context>
    <name>StrapsText</name>
    <message>
        <source>Straps checked from the movement: upper-arm sensor turned %1 deg, forearm sensor turned %2 deg and %3 cm from the wrist</source>
        <translation>Cintas comprobadas a partir del movimiento: sensor del brazo girado %1°, sensor del antebrazo girado %2° y a %3 cm de la muñeca</translation>
    </message>
    <message>
        <source>Straps: not checked yet (the arm needs a moment of rest and more movement)</source>
        <translation>Cintas: aún no comprobadas (el brazo necesita un momento de reposo y más movimiento)</translation>
    </message>
    <message>
        <source>Straps: checking them from the movement…</source>
        <translation>Cintas: se comprueban a partir del movimiento…</translation>
    </message>
    <message>
        <source>Straps as fitted (checked from the movement)</source>
        <translation>Cintas tal como se colocaron (comprobadas a partir del movimiento)</translation>
    </message>
    <message>
        <source>A sensor strap has turned on your arm. Your exercise is still measured; next time, put the straps on as shown before you start.</source>
        <translation>Una cinta de sensor se ha girado en su brazo. Su ejercicio se sigue midiendo; la próxima vez, colóquese las cintas como se muestra antes de empezar.</translation>
    </message>
    <message>
        <source>Straps: checking them from the movement (rest still a moment with the upper arm hanging, the elbow bent to a right angle and the thumb up, then move)</source>
        <translation>Cintas: se comprueban a partir del movimiento (descanse quieto un momento con el brazo colgando, el codo doblado en ángulo recto y el pulgar hacia arriba; después muévase)</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CalibrationGuide</name>
    <message>
        <source>Arm forward</source>
        <translation>Brazo hacia delante</translation>
    </message>
    <message>
        <source>Raise the arm forward to shoulder height, elbow almost straight.</source>
        <translation>Elevar el brazo hacia delante hasta la altura del hombro, con el codo casi extendido.</translation>
    </message>
    <message>
        <source>Arm to the side</source>
        <translation>Brazo al lado</translation>
    </message>
    <message>
        <source>Lift the arm out to the side, about 60 degrees, elbow almost straight.</source>
        <translation>Separar el brazo hacia el lado unos 60 grados, con el codo casi extendido.</translation>
    </message>
    <message>
        <source>Hand across</source>
        <translation>Mano cruzada</translation>
    </message>
    <message>
        <source>Bring the hand across the body, elbow at a right angle, palm down.</source>
        <translation>Llevar la mano por delante del cuerpo hacia el otro lado, con el codo en ángulo recto y la palma hacia abajo.</translation>
    </message>
    <message>
        <source>Hand out</source>
        <translation>Mano hacia fuera</translation>
    </message>
    <message>
        <source>Take the hand out to the side, elbow bent, palm up.</source>
        <translation>Llevar la mano hacia fuera, al lado, con el codo flexionado y la palma hacia arriba.</translation>
    </message>
    <message>
        <source>Sit upright. Let the upper arm hang at the side, bend the elbow to a right angle, forearm pointing straight forward, thumb up. Keep still.</source>
        <translation>Siéntese erguido. Deje colgar el brazo junto al cuerpo, flexione el codo en ángulo recto con el antebrazo apuntando al frente y el pulgar hacia arriba. Quédese quieto.</translation>
    </message>
    <message>
        <source>Hold still.</source>
        <translation>Quédese quieto.</translation>
    </message>
    <message>
        <source>Start pose</source>
        <translation>Posición inicial</translation>
    </message>
    <message>
        <source>Elbow bends</source>
        <translation>Flexiones de codo</translation>
    </message>
    <message>
        <source>Bend and straighten the elbow four times, turning the palm down while straightening and up while bending.</source>
        <translation>Flexionar y extender el codo cuatro veces, girando la palma hacia abajo al extender y hacia arriba al flexionar.</translation>
    </message>
    <message>
        <source>Shoulder rotation</source>
        <translation>Rotación de hombro</translation>
    </message>
    <message>
        <source>Elbow at a right angle: swing the hand in to the belly and out, three times.</source>
        <translation>Con el codo en ángulo recto, llevar la mano hacia el abdomen y hacia fuera, tres veces.</translation>
    </message>
    <message>
        <source>Reach and mouth</source>
        <translation>Alcanzar y a la boca</translation>
    </message>
    <message>
        <source>Reach forward and up, then bring the hand to the mouth; three times.</source>
        <translation>Alcanzar hacia delante y arriba y luego llevar la mano a la boca; tres veces.</translation>
    </message>
    <message>
        <source>Arm out and across</source>
        <translation>Brazo fuera y cruzado</translation>
    </message>
    <message>
        <source>Lift the arm out to the side, then bring it back across; three times.</source>
        <translation>Separar el brazo hacia el lado y luego cruzarlo por delante del cuerpo; tres veces.</translation>
    </message>
    <message>
        <source>Back to the start pose</source>
        <translation>Volver a la posición inicial</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CameraCalibrationPage</name>
    <message>
        <source>Camera calibration</source>
        <translation>Calibración de la cámara</translation>
    </message>
    <message>
        <source>Starting the camera…</source>
        <translation>Iniciando la cámara…</translation>
    </message>
    <message>
        <source>Camera picture</source>
        <translation>Imagen de la cámara</translation>
    </message>
    <message>
        <source>Hold the printed chessboard (%1 x %2 inner corners) in front of the camera. Capture views with the board in every part of the picture, near and far, tilted a little.</source>
        <translation>Sostenga el tablero de ajedrez impreso (%1 × %2 esquinas interiores) delante de la cámara. Capture vistas con el tablero en todas las zonas de la imagen, cerca y lejos, ligeramente inclinado.</translation>
    </message>
    <message>
        <source>Capture &amp;automatically when the board covers new ground</source>
        <translation>Capturar &amp;automáticamente cuando el tablero cubra zonas nuevas</translation>
    </message>
    <message>
        <source>&amp;Capture view</source>
        <translation>&amp;Capturar vista</translation>
    </message>
    <message>
        <source>Ca&amp;librate</source>
        <translation>Ca&amp;librar</translation>
    </message>
    <message>
        <source>&amp;Start over</source>
        <translation>&amp;Empezar de nuevo</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Cobertura</translation>
    </message>
    <message>
        <source>Camera calibration verdict</source>
        <translation>Resultado de la calibración de la cámara</translation>
    </message>
    <message>
        <source>Check that the camera is plugged in and not used by another program.</source>
        <translation>Compruebe que la cámara está conectada y que ningún otro programa la está usando.</translation>
    </message>
    <message>
        <source>Could not calibrate: %1</source>
        <translation>No se pudo calibrar: %1</translation>
    </message>
    <message>
        <source>Good.</source>
        <translation>Buena.</translation>
    </message>
    <message>
        <source>Usable; more views, sharper and better lit, would improve it.</source>
        <translation>Aceptable; más vistas, más nítidas y mejor iluminadas, la mejorarían.</translation>
    </message>
    <message>
        <source>Poor: capture the views again, holding the board still and flat.</source>
        <translation>Deficiente: capture de nuevo las vistas sosteniendo el tablero quieto y plano.</translation>
    </message>
    <message>
        <source>The boards covered only %1 % of the picture; views near the edges help most.</source>
        <translation>Los tableros cubrieron solo el %1 % de la imagen; las vistas cerca de los bordes son las que más ayudan.</translation>
    </message>
    <message>
        <source>Capture at least 4 views first (%1 so far); 10 or more spread over the picture give a good calibration.</source>
        <translation>Capture primero al menos 4 vistas (hasta ahora %1); 10 o más repartidas por la imagen dan una buena calibración.</translation>
    </message>
    <message>
        <source>Calibrating…</source>
        <translation>Calibrando…</translation>
    </message>
    <message>
        <source>%1 views kept; the boards cover %2 % of the picture.</source>
        <translation>%1 vistas guardadas; los tableros cubren el %2 % de la imagen.</translation>
    </message>
    <message>
        <source>Reprojection error %L1 px over %2 views; fx %L3, fy %L4 px.</source>
        <translation>Error de reproyección de %L1 px en %2 vistas; fx %L3, fy %L4 px.</translation>
    </message>
    <message>
        <source>No device among those chosen gives webcam images or marker pixels: nothing to calibrate here.</source>
        <translation>Ninguno de los dispositivos elegidos da imágenes de webcam ni píxeles de marcadores: aquí no hay nada que calibrar.</translation>
    </message>
    <message>
        <source>The webcam of %1 brings its own camera model (it is simulated or replayed), so there is no chessboard to show it: nothing to calibrate here.</source>
        <translation>La webcam de %1 trae su propio modelo de cámara (es simulada o reproducida), así que no se le puede mostrar un tablero: aquí no hay nada que calibrar.</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::CameraCalibrationWorker</name>
    <message>
        <source>No picture from the camera.</source>
        <translation>La cámara no da imagen.</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::DevicesPage</name>
    <message>
        <source>Devices</source>
        <translation>Dispositivos</translation>
    </message>
    <message>
        <source>&amp;Devices found (tick the ones to use):</source>
        <translation>&amp;Dispositivos encontrados (marque los que va a usar):</translation>
    </message>
    <message>
        <source>Device plugins</source>
        <translation>Complementos de dispositivos</translation>
    </message>
    <message>
        <source>Not loaded: %1</source>
        <translation>No cargados: %1</translation>
    </message>
    <message>
        <source>&amp;Check connection</source>
        <translation>&amp;Comprobar conexión</translation>
    </message>
    <message>
        <source>Check connection</source>
        <translation>Comprobar conexión</translation>
    </message>
    <message>
        <source>Choose the devices, then check their connection.</source>
        <translation>Elija los dispositivos y después compruebe su conexión.</translation>
    </message>
    <message>
        <source>Connection check</source>
        <translation>Comprobación de la conexión</translation>
    </message>
    <message>
        <source>The devices could not start: %1</source>
        <translation>Los dispositivos no pudieron arrancar: %1</translation>
    </message>
    <message>
        <source>Not found: %1. Check the plugin folders in the settings.</source>
        <translation>No encontrados: %1. Revise las carpetas de complementos en los ajustes.</translation>
    </message>
    <message>
        <source>Tick at least one device first.</source>
        <translation>Marque primero al menos un dispositivo.</translation>
    </message>
    <message>
        <source>Stop &amp;check</source>
        <translation>Detener la &amp;comprobación</translation>
    </message>
    <message>
        <source>Starting the devices…</source>
        <translation>Iniciando los dispositivos…</translation>
    </message>
    <message>
        <source>Connected: %1.</source>
        <translation>Conectado: %1.</translation>
    </message>
    <message>
        <source>Receiving from every device…</source>
        <translation>Recibiendo de todos los dispositivos…</translation>
    </message>
    <message>
        <source>Not every device is streaming: %1. Check that each is switched on, charged and within range, then check again.</source>
        <translation>No todos los dispositivos transmiten: %1. Compruebe que cada uno está encendido, cargado y dentro del alcance, y vuelva a comprobar.</translation>
    </message>
    <message>
        <source>Check stopped.</source>
        <translation>Comprobación detenida.</translation>
    </message>
    <message>
        <source>%1 %2 %L3 Hz</source>
        <translation>%1 %2 %L3 Hz</translation>
    </message>
    <message>
        <source>%1 %L2 % (low: charge it after the session)</source>
        <translation>%1 %L2 % (baja: cárguela después de la sesión)</translation>
    </message>
    <message>
        <source>%1 %L2 %</source>
        <translation>%1 %L2 %</translation>
    </message>
    <message>
        <source>Battery: %1.</source>
        <translation>Batería: %1.</translation>
    </message>
    <message>
        <source>The angles keep following the arm: move it and check them, then go on (or stop the check).</source>
        <translation>Los ángulos siguen al brazo: muévalo y compruébelos, luego continúe (o detenga la comprobación).</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::LiveSessionScreen</name>
    <message>
        <source>Live session</source>
        <translation>Sesión en directo</translation>
    </message>
    <message>
        <source>%1. The session goes on with the other sensors; check the device (power, cable or distance).</source>
        <translation>%1. La sesión continúa con los demás sensores; revise el dispositivo (alimentación, cable o distancia).</translation>
    </message>
    <message>
        <source>left arm</source>
        <translation>brazo izquierdo</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>brazo derecho</translation>
    </message>
    <message>
        <source>Live session, %1</source>
        <translation>Sesión en directo, %1</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>Session status</source>
        <translation>Estado de la sesión</translation>
    </message>
    <message>
        <source>&amp;Record</source>
        <translation>&amp;Grabar</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Detener</translation>
    </message>
    <message>
        <source>Pain</source>
        <translation>Dolor</translation>
    </message>
    <message>
        <source>Rest</source>
        <translation>Descanso</translation>
    </message>
    <message>
        <source>Fatigue</source>
        <translation>Fatiga</translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation>Compensación</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <source>Event label</source>
        <translation>Etiqueta del evento</translation>
    </message>
    <message>
        <source>&amp;Mark event</source>
        <translation>&amp;Marcar evento</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>Problema</translation>
    </message>
    <message>
        <source>Try &amp;again</source>
        <translation>&amp;Reintentar</translation>
    </message>
    <message>
        <source>Session messages</source>
        <translation>Mensajes de la sesión</translation>
    </message>
    <message>
        <source>Could not start the session: %1</source>
        <translation>No se pudo iniciar la sesión: %1</translation>
    </message>
    <message>
        <source>Session started</source>
        <translation>Sesión iniciada</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Grabando en %1</translation>
    </message>
    <message>
        <source>Last recording problem: %1</source>
        <translation>Último problema de grabación: %1</translation>
    </message>
    <message>
        <source>Session ended; nothing was recorded.</source>
        <translation>Sesión terminada; no se grabó nada.</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>Evento</translation>
    </message>
    <message>
        <source>Recording stopped: %1</source>
        <translation>Grabación detenida: %1</translation>
    </message>
    <message>
        <source>This session is not recorded</source>
        <translation>Esta sesión no se graba</translation>
    </message>
    <message>
        <source>Not started</source>
        <translation>Sin iniciar</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Iniciando…</translation>
    </message>
    <message>
        <source>Live %1 (not recording)</source>
        <translation>En directo %1 (sin grabar)</translation>
    </message>
    <message>
        <source>● Recording %1</source>
        <translation>● Grabando %1</translation>
    </message>
    <message>
        <source>Paused (%1 recorded)</source>
        <translation>En pausa (%1 grabado)</translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation>Deteniendo…</translation>
    </message>
    <message>
        <source>Ended</source>
        <translation>Terminada</translation>
    </message>
    <message>
        <source>Not running</source>
        <translation>Detenida</translation>
    </message>
    <message>
        <source>Live session: %1</source>
        <translation>Sesión en directo: %1</translation>
    </message>
    <message>
        <source>Pause recording; the live view goes on (%1)</source>
        <translation>Pausar la grabación; la vista en directo continúa (%1)</translation>
    </message>
    <message>
        <source>End the session (%1)</source>
        <translation>Terminar la sesión (%1)</translation>
    </message>
    <message>
        <source>Mark the chosen event at the current time (%1)</source>
        <translation>Marcar el evento elegido en el momento actual (%1)</translation>
    </message>
    <message>
        <source>Recording resumed at %L1 s</source>
        <translation>Grabación reanudada a los %L1 s</translation>
    </message>
    <message>
        <source>Recording paused at %L1 s</source>
        <translation>Grabación en pausa a los %L1 s</translation>
    </message>
    <message>
        <source>%1 marked at %L2 s</source>
        <translation>%1 marcado a los %L2 s</translation>
    </message>
    <message>
        <source>Start or resume recording to %1 (%2)</source>
        <translation>Iniciar o reanudar la grabación en %1 (%2)</translation>
    </message>
    <message>
        <source>Straps</source>
        <translation>Cintas</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::LiveTrunkFeedback</name>
    <message>
        <source>Trunk: flexion %1, lateral bending %2, axial rotation %3</source>
        <translation>Tronco: flexión %1, inclinación lateral %2, rotación axial %3</translation>
    </message>
    <message>
        <source>The trunk moved: shoulder angles include the lean.</source>
        <translation>El tronco se ha movido: los ángulos del hombro incluyen la inclinación.</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) with compensation</source>
        <translation>
            <numerusform>%n repetición con compensación</numerusform>
            <numerusform>%n repeticiones con compensación</numerusform>
        </translation>
    </message>
    <message>
        <source>(trunk limit %1)</source>
        <translation>(límite del tronco %1)</translation>
    </message>
    <message>
        <source>Keep your back against the chair</source>
        <translation>Mantenga la espalda contra la silla</translation>
    </message>
    <message>
        <source>Trunk cue</source>
        <translation>Aviso del tronco</translation>
    </message>
    <message>
        <source>Trunk</source>
        <translation>Tronco</translation>
    </message>
    <message>
        <source>Repetitions with compensation</source>
        <translation>Repeticiones con compensación</translation>
    </message>
    <message>
        <source>Trunk limit %1: %2 of %3 repetitions with compensation</source>
        <translation>Límite del tronco %1: %2 de %3 repeticiones con compensación</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::RecordingTarget</name>
    <message>
        <source>a recording with this name exists; choose another name</source>
        <translation>ya existe una grabación con este nombre; elija otro nombre</translation>
    </message>
    <message>
        <source>the records of patient %1</source>
        <translation>el historial del paciente %1</translation>
    </message>
    <message>
        <source>cannot record into the records: %1</source>
        <translation>no se puede grabar en los registros clínicos: %1</translation>
    </message>
    <message>
        <source>%L1 rows recorded in %2</source>
        <translation>%L1 filas grabadas en %2</translation>
    </message>
    <message>
        <source>%L1 rows recorded in %2; some rows could not be written</source>
        <translation>%L1 filas grabadas en %2; algunas filas no se pudieron escribir</translation>
    </message>
    <message>
        <source>session %1: %L2 rows recorded, but it could not be closed: %3</source>
        <translation>sesión %1: %L2 filas grabadas, pero no se pudo cerrar: %3</translation>
    </message>
    <message>
        <source>session %1 saved in the records: %L2 rows</source>
        <translation>sesión %1 guardada en los registros clínicos: %L2 filas</translation>
    </message>
    <message>
        <source>cannot create the folder %1 (%2): choose a folder you may write to</source>
        <translation>no se puede crear la carpeta %1 (%2): elija una carpeta en la que pueda escribir</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::SensorCalibrationPage</name>
    <message>
        <source>upper-arm gyroscope</source>
        <translation>giroscopio del brazo</translation>
    </message>
    <message>
        <source>upper-arm accelerometer</source>
        <translation>acelerómetro del brazo</translation>
    </message>
    <message>
        <source>forearm gyroscope</source>
        <translation>giroscopio del antebrazo</translation>
    </message>
    <message>
        <source>forearm accelerometer</source>
        <translation>acelerómetro del antebrazo</translation>
    </message>
    <message>
        <source>optical positions</source>
        <translation>posiciones ópticas</translation>
    </message>
    <message>
        <source>Sensor calibration</source>
        <translation>Calibración de los sensores</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Instrucción</translation>
    </message>
    <message>
        <source>Time left in this step</source>
        <translation>Tiempo restante de este paso</translation>
    </message>
    <message>
        <source>Protocol progress</source>
        <translation>Progreso del protocolo</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Iniciar</translation>
    </message>
    <message>
        <source>C&amp;ancel</source>
        <translation>C&amp;ancelar</translation>
    </message>
    <message>
        <source>Calibration verdict</source>
        <translation>Resultado de la calibración</translation>
    </message>
    <message>
        <source>Calibration details</source>
        <translation>Detalles de la calibración</translation>
    </message>
    <message>
        <source>The devices could not start: %1</source>
        <translation>Los dispositivos no pudieron arrancar: %1</translation>
    </message>
    <message>
        <source>The protocol could not be recorded: %1</source>
        <translation>No se pudo grabar el protocolo: %1</translation>
    </message>
    <message>
        <source>no data arrived</source>
        <translation>no llegaron datos</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Repetir</translation>
    </message>
    <message>
        <source>Starting the sensors…</source>
        <translation>Iniciando los sensores…</translation>
    </message>
    <message>
        <source>Recorded</source>
        <translation>Grabado</translation>
    </message>
    <message>
        <source>The patient can relax.</source>
        <translation>El paciente puede relajarse.</translation>
    </message>
    <message>
        <source>Calibrating…</source>
        <translation>Calibrando…</translation>
    </message>
    <message>
        <source>Fitting the sensors&apos; mounting to the recording (this takes a few seconds).</source>
        <translation>Ajustando la colocación de los sensores a la grabación (tarda unos segundos).</translation>
    </message>
    <message>
        <source>The calibration failed: %1. Redo the protocol.</source>
        <translation>La calibración ha fallado: %1. Repita el protocolo.</translation>
    </message>
    <message>
        <source>Upper-arm strap angle %1 deg, forearm strap angle %2 deg; residuals (noise levels): upper gyro %3, upper acc %4, forearm gyro %5, forearm acc %6, optical %7; %8 iterations.</source>
        <translation>Ángulo de la correa del brazo %1°, ángulo de la correa del antebrazo %2°; residuos (niveles de ruido): giro brazo %3, acel. brazo %4, giro antebrazo %5, acel. antebrazo %6, óptico %7; %8 iteraciones.</translation>
    </message>
    <message>
        <source>Calibration done</source>
        <translation>Calibración terminada</translation>
    </message>
    <message>
        <source>Cancelled. Press Start to begin the protocol again.</source>
        <translation>Cancelado. Pulse «Iniciar» para empezar de nuevo el protocolo.</translation>
    </message>
    <message>
        <source>The fit did not settle. Check that both sensors are strapped tight, then redo the protocol.</source>
        <translation>El ajuste no convergió. Compruebe que los dos sensores están bien sujetos y repita el protocolo.</translation>
    </message>
    <message>
        <source>The movements do not fit the arm model well (%1 off by %2 noise levels). Check the straps and the start pose, then redo the protocol.</source>
        <translation>Los movimientos no encajan bien con el modelo del brazo (%1 se desvía %2 niveles de ruido). Revise las correas y la posición inicial y repita el protocolo.</translation>
    </message>
    <message>
        <source>Usable, not perfect (worst: %1 at %2 noise levels).</source>
        <translation>Aceptable, no perfecta (lo peor: %1 con %2 niveles de ruido).</translation>
    </message>
    <message>
        <source>Redo the protocol for a better one.</source>
        <translation>Repita el protocolo para obtener una mejor.</translation>
    </message>
    <message>
        <source>Good: the data fit the arm model to the sensors&apos; noise level (worst: %1 at %2).</source>
        <translation>Buena: los datos encajan con el modelo del brazo hasta el nivel de ruido de los sensores (lo peor: %1 con %2).</translation>
    </message>
    <message numerus="yes">
        <source>Hold still: %n s</source>
        <translation>
            <numerusform>Quieto: %n s</numerusform>
            <numerusform>Quieto: %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Move: %n s</source>
        <translation>
            <numerusform>Mover: %n s</numerusform>
            <numerusform>Mover: %n s</numerusform>
        </translation>
    </message>
    <message>
        <source>The patient sits upright with both sensors strapped on. Press Start, then follow the instructions on the screen for about a minute.</source>
        <translation>El paciente está sentado erguido con los dos sensores colocados. Pulse «Iniciar» y siga las instrucciones de la pantalla durante un minuto aproximadamente.</translation>
    </message>
    <message>
        <source>Done: the calibration is good.</source>
        <translation>Listo: la calibración es buena.</translation>
    </message>
    <message>
        <source>Done: the calibration can be used. If you have a minute, press Redo for a better one.</source>
        <translation>Listo: la calibración se puede usar. Si tiene un minuto, pulse Repetir para obtener una mejor.</translation>
    </message>
    <message>
        <source>That did not work this time. Check that both straps are tight, then press Redo and follow the screen again, or go on without it.</source>
        <translation>Esta vez no ha funcionado. Compruebe que las dos correas estén firmes, pulse Repetir y siga de nuevo la pantalla, o continúe sin ella.</translation>
    </message>
    <message>
        <source>You can relax.</source>
        <translation>Ya puede relajarse.</translation>
    </message>
    <message>
        <source>You can relax. ArmTrack is working this out; it takes a few seconds.</source>
        <translation>Ya puede relajarse. ArmTrack lo está calculando; tarda unos segundos.</translation>
    </message>
    <message>
        <source>Chest (sternum) sensor: its tilt is taken from the upright start pose; its heading about the vertical is kept as assumed.</source>
        <translation>Sensor del pecho (esternón): su inclinación se toma de la postura inicial erguida; su orientación alrededor de la vertical se mantiene como se supuso.</translation>
    </message>
    <message>
        <source>The fit did not settle. Check that all three sensors are strapped tight, then redo the protocol.</source>
        <translation>El ajuste no convergió. Compruebe que los tres sensores están bien sujetos y repita el protocolo.</translation>
    </message>
    <message>
        <source>The patient sits upright with all three sensors (upper arm, forearm and chest) strapped on. Press Start, then follow the instructions on the screen for about a minute.</source>
        <translation>El paciente está sentado erguido con los tres sensores (brazo, antebrazo y pecho) colocados. Pulse «Iniciar» y siga las instrucciones de la pantalla durante un minuto aproximadamente.</translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::SessionController</name>
    <message>
        <source>a session is already running; stop it first</source>
        <translation>ya hay una sesión en curso; deténgala primero</translation>
    </message>
    <message>
        <source>no device chosen: choose at least one device</source>
        <translation>no se ha elegido ningún dispositivo: elija al menos uno</translation>
    </message>
    <message>
        <source>no device plugin &quot;%1&quot;; found: %2. Check the plugin folders in the settings.</source>
        <translation>no hay ningún complemento de dispositivo «%1»; encontrados: %2. Revise las carpetas de complementos en los ajustes.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>the session could not start: %1</source>
        <translation>la sesión no pudo iniciarse: %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::AppController</name>
    <message>
        <source>Preparing the demo</source>
        <translation>Preparando la demostración</translation>
    </message>
    <message>
        <source>Making demo records in %1: three patients, two protocols and six weeks of sessions, simulated and analysed the way real ones are. This takes a few seconds.</source>
        <translation>Creando registros de demostración en %1: tres pacientes, dos protocolos y seis semanas de sesiones, simuladas y analizadas como las reales. Tarda unos segundos.</translation>
    </message>
    <message>
        <source>Signing in as the demo therapist...</source>
        <translation>Entrando como terapeuta de demostración...</translation>
    </message>
    <message>
        <source>%1 (%2, demo)</source>
        <translation>%1 (%2, demostración)</translation>
    </message>
    <message>
        <source>Demo records: accounts &quot;%1&quot; and &quot;%2&quot;, password &quot;%3&quot;.</source>
        <translation>Registros de demostración: cuentas «%1» y «%2», contraseña «%3».</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Cancelar</translation>
    </message>
    <message>
        <source>Settings saved.</source>
        <translation>Ajustes guardados.</translation>
    </message>
    <message>
        <source>The new records location is used at the next sign-in.</source>
        <translation>La nueva ubicación de los registros se usará en el próximo acceso.</translation>
    </message>
    <message>
        <source>Opening the records</source>
        <translation>Abriendo los registros clínicos</translation>
    </message>
    <message>
        <source>Opening %1...</source>
        <translation>Abriendo %1...</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Analysing the session</source>
        <translation>Analizando la sesión</translation>
    </message>
    <message>
        <source>Estimating the joint angles of session %1 again from its recording and computing its metrics...</source>
        <translation>Recalculando los ángulos articulares de la sesión %1 a partir de su grabación y calculando sus métricas...</translation>
    </message>
    <message>
        <source>Session %1 is saved, but it could not be analysed: %2
You can re-estimate it from its review.</source>
        <translation>La sesión %1 está guardada, pero no se pudo analizar: %2
Puede recalcularla desde su revisión.</translation>
    </message>
    <message>
        <source>&amp;Review session</source>
        <translation>&amp;Revisar la sesión</translation>
    </message>
    <message>
        <source>&amp;Back to the patient</source>
        <translation>&amp;Volver al paciente</translation>
    </message>
    <message>
        <source>&amp;Skip the analysis</source>
        <translation>&amp;Omitir el análisis</translation>
    </message>
    <message>
        <source>Back the file up, then bring it up to date with: armtrack-cli db migrate</source>
        <translation>Haga una copia de seguridad del archivo y actualícelo después con: armtrack-cli db migrate</translation>
    </message>
    <message>
        <source>Install the newer ArmTrack that wrote it.</source>
        <translation>Instale la versión más reciente de ArmTrack que lo escribió.</translation>
    </message>
    <message>
        <source>The file was left untouched. Restore it from a backup, or choose another database in the settings.</source>
        <translation>El archivo no se ha tocado. Restáurelo desde una copia de seguridad o elija otra base de datos en los ajustes.</translation>
    </message>
    <message>
        <source>Check the location in the settings (or --db) and that you may read and write it, then try again.</source>
        <translation>Compruebe la ubicación en los ajustes (o --db) y que tiene permiso de lectura y escritura, y vuelva a intentarlo.</translation>
    </message>
    <message>
        <source>The records cannot be opened</source>
        <translation>No se pueden abrir los registros clínicos</translation>
    </message>
    <message>
        <source>&amp;Try again</source>
        <translation>&amp;Reintentar</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>administrator</source>
        <translation>administrador</translation>
    </message>
    <message>
        <source>therapist</source>
        <translation>terapeuta</translation>
    </message>
    <message>
        <source>home account</source>
        <translation>cuenta para casa</translation>
    </message>
    <message>
        <source>Signing in as the demo patient at home...</source>
        <translation>Iniciando sesión como la paciente de demostración en casa...</translation>
    </message>
    <message numerus="yes">
        <source>%n earlier session(s) analysed</source>
        <translation>
            <numerusform>%n sesión anterior analizada</numerusform>
            <numerusform>%n sesiones anteriores analizadas</numerusform>
        </translation>
    </message>
    <message>
        <source>Earlier sessions could not be analysed now: %1</source>
        <translation>Las sesiones anteriores no se pudieron analizar ahora: %1</translation>
    </message>
    <message>
        <source>Session %1 was too short to analyse: %2 s were recorded, and at least %3 s are needed. It is kept, marked as too short.
To measure the movement, start a new session, press Record, let the patient do the movement, then press Stop.</source>
        <translation>La sesión %1 fue demasiado corta para analizarla: se grabaron %2 s y hacen falta al menos %3 s. Se conserva, marcada como demasiado corta.
Para medir el movimiento, inicie una sesión nueva, pulse Grabar, deje que el paciente haga el movimiento y pulse Detener.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::BirthDateField</name>
    <message>
        <source>not given</source>
        <translation>no indicada</translation>
    </message>
    <message>
        <source>Birth date</source>
        <translation>Fecha de nacimiento</translation>
    </message>
    <message>
        <source>Type the date as %1 or %2; leave it empty when not given. Up and Down change it by a day, Alt+Down opens a calendar.</source>
        <translation>Escriba la fecha como %1 o %2; déjela vacía si no se indica. Arriba y Abajo la cambian en un día, Alt+Abajo abre un calendario.</translation>
    </message>
    <message>
        <source>Choose the birth date from a calendar</source>
        <translation>Elegir la fecha de nacimiento en un calendario</translation>
    </message>
    <message>
        <source>a birth date from %1 up to today, %2</source>
        <translation>una fecha de nacimiento del %1 hasta hoy, %2</translation>
    </message>
    <message>
        <source>Born: &quot;%1&quot; is not a date. Type %2 as %3 or %4, or leave the field empty when the birth date is not given.</source>
        <translation>Nacimiento: «%1» no es una fecha. Escriba %2 como %3 o %4, o deje el campo vacío si no se indica la fecha de nacimiento.</translation>
    </message>
    <message>
        <source>Born: %1 is not possible. Type %2.</source>
        <translation>Nacimiento: %1 no es posible. Escriba %2.</translation>
    </message>
    <message>
        <source>Calendar</source>
        <translation>Calendario</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::CloseWhileRecording</name>
    <message>
        <source>A recording is under way</source>
        <translation>Hay una grabación en curso</translation>
    </message>
    <message>
        <source>Stop the recording and save the session before closing?</source>
        <translation>¿Detener la grabación y guardar la sesión antes de cerrar?</translation>
    </message>
    <message>
        <source>Stop and save ends the session as the Stop button does and closes ArmTrack; the session is analysed when ArmTrack next starts. Keep recording goes back to the session.</source>
        <translation>Detener y guardar termina la sesión como el botón Detener y cierra ArmTrack; la sesión se analiza la próxima vez que se inicie ArmTrack. Seguir grabando vuelve a la sesión.</translation>
    </message>
    <message>
        <source>&amp;Stop and save</source>
        <translation>&amp;Detener y guardar</translation>
    </message>
    <message>
        <source>&amp;Keep recording</source>
        <translation>&amp;Seguir grabando</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::DeviceTableModel</name>
    <message>
        <source>Device %1</source>
        <translation>Dispositivo %1</translation>
    </message>
    <message>
        <source>device %1</source>
        <translation>dispositivo %1</translation>
    </message>
    <message>
        <source>never</source>
        <translation>nunca</translation>
    </message>
    <message>
        <source>enrolled</source>
        <translation>registrado</translation>
    </message>
    <message>
        <source>revoked %1</source>
        <translation>revocado %1</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Dispositivo</translation>
    </message>
    <message>
        <source>Enrolled</source>
        <translation>Registrado</translation>
    </message>
    <message>
        <source>Last sync</source>
        <translation>Última sincronización</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::FirstRunScreen</name>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Examinar...</translation>
    </message>
    <message>
        <source>&amp;Create and sign in</source>
        <translation>&amp;Crear y entrar</translation>
    </message>
    <message>
        <source>First start</source>
        <translation>Primer inicio</translation>
    </message>
    <message>
        <source>Welcome to ArmTrack</source>
        <translation>Bienvenido a ArmTrack</translation>
    </message>
    <message>
        <source>Where the data lives</source>
        <translation>Dónde se guardan los datos</translation>
    </message>
    <message>
        <source>The database given on the command line: %1</source>
        <translation>La base de datos indicada en la línea de órdenes: %1</translation>
    </message>
    <message>
        <source>Data folder</source>
        <translation>Carpeta de datos</translation>
    </message>
    <message>
        <source>Choose the data folder</source>
        <translation>Elegir la carpeta de datos</translation>
    </message>
    <message>
        <source>Administrator account</source>
        <translation>Cuenta de administrador</translation>
    </message>
    <message>
        <source>Administrator name</source>
        <translation>Nombre del administrador</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Contraseña</translation>
    </message>
    <message numerus="yes">
        <source>at least %n characters</source>
        <translation>
            <numerusform>al menos %n carácter</numerusform>
            <numerusform>al menos %n caracteres</numerusform>
        </translation>
    </message>
    <message>
        <source>Password again</source>
        <translation>Repetir la contraseña</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Contraseña:</translation>
    </message>
    <message>
        <source>Password &amp;again:</source>
        <translation>&amp;Repetir la contraseña:</translation>
    </message>
    <message>
        <source>Choose a folder.</source>
        <translation>Elija una carpeta.</translation>
    </message>
    <message>
        <source>The records will be kept in %1.</source>
        <translation>Los registros clínicos se guardarán en %1.</translation>
    </message>
    <message>
        <source>Where ArmTrack keeps its data</source>
        <translation>Dónde guarda ArmTrack sus datos</translation>
    </message>
    <message>
        <source>Choose the folder where ArmTrack keeps its data.</source>
        <translation>Elija la carpeta donde ArmTrack guarda sus datos.</translation>
    </message>
    <message>
        <source>Give the data folder as a full path, e.g. %1.</source>
        <translation>Indique la carpeta de datos con su ruta completa, p. ej. %1.</translation>
    </message>
    <message>
        <source>Give the administrator a name.</source>
        <translation>Dé un nombre al administrador.</translation>
    </message>
    <message numerus="yes">
        <source>The password needs at least %n characters.</source>
        <translation>
            <numerusform>La contraseña necesita al menos %n carácter.</numerusform>
            <numerusform>La contraseña necesita al menos %n caracteres.</numerusform>
        </translation>
    </message>
    <message>
        <source>The two passwords differ. Type the same password twice.</source>
        <translation>Las dos contraseñas no coinciden. Escriba dos veces la misma contraseña.</translation>
    </message>
    <message>
        <source>Creating the records...</source>
        <translation>Creando los registros clínicos...</translation>
    </message>
    <message>
        <source>ArmTrack keeps its patients, sessions and recordings in one database. Choose where it lives and create the administrator account; the administrator then adds the therapists&apos; accounts, the protocols and the home programmes under ArmTrack &gt; Administration.</source>
        <translation>ArmTrack guarda sus pacientes, sesiones y grabaciones en una base de datos. Elija dónde se guarda y cree la cuenta de administrador; el administrador añade después las cuentas de los terapeutas, los protocolos y los programas en casa en ArmTrack &gt; Administración.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::HelpWindow</name>
    <message>
        <source>Choose where the records are kept and name the administrator; then press Create.</source>
        <translation>Elija dónde se guardan los registros y nombre al administrador; luego pulse Crear.</translation>
    </message>
    <message>
        <source>Type your account name and password, then press Sign in.</source>
        <translation>Escriba su nombre de cuenta y su contraseña y pulse Iniciar sesión.</translation>
    </message>
    <message>
        <source>Find a patient by name or code and open their page (Enter), or add a new patient (Ctrl+N).</source>
        <translation>Busque un paciente por nombre o código y abra su página (Intro), o añada un paciente nuevo (Ctrl+N).</translation>
    </message>
    <message>
        <source>See the patient&apos;s sessions and progress; start a new session (Ctrl+R) or open a session to review it (Enter).</source>
        <translation>Vea las sesiones y el progreso del paciente; inicie una sesión nueva (Ctrl+R) o abra una sesión para revisarla (Intro).</translation>
    </message>
    <message>
        <source>Go through the steps: protocol and arm, the device check, the sensors&apos; calibration and the camera; Finish starts the session.</source>
        <translation>Siga los pasos: protocolo y brazo, la comprobación de los dispositivos, la calibración de los sensores y la cámara; Finalizar inicia la sesión.</translation>
    </message>
    <message>
        <source>Watch the arm and the angles; press Record (Ctrl+R) to keep the movement and Stop (Ctrl+E) when the exercise is done.</source>
        <translation>Observe el brazo y los ángulos; pulse Grabar (Ctrl+R) para guardar el movimiento y Detener (Ctrl+E) al terminar el ejercicio.</translation>
    </message>
    <message>
        <source>Move through the session with the slider or by clicking a plot; compare, re-estimate or write a report.</source>
        <translation>Recorra la sesión con el control deslizante o haciendo clic en un gráfico; compare, vuelva a estimar o escriba un informe.</translation>
    </message>
    <message>
        <source>The guide describes every screen; its contents are at the top.</source>
        <translation>La guía describe cada pantalla; su contenido está al principio.</translation>
    </message>
    <message>
        <source>ArmTrack user guide</source>
        <translation>Guía de usuario de ArmTrack</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>Guía de usuario</translation>
    </message>
    <message>
        <source>What to do here</source>
        <translation>Qué hacer aquí</translation>
    </message>
    <message>
        <source>The guide is not yet translated into your language; it is shown in English.</source>
        <translation>La guía aún no está traducida a su idioma; se muestra en inglés.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::HomeDevicesBox</name>
    <message>
        <source>The code is copied.</source>
        <translation>El código está copiado.</translation>
    </message>
    <message>
        <source>Home devices</source>
        <translation>Dispositivos domésticos</translation>
    </message>
    <message>
        <source>Home &amp;account:</source>
        <translation>&amp;Cuenta doméstica:</translation>
    </message>
    <message>
        <source>Home account</source>
        <translation>Cuenta doméstica</translation>
    </message>
    <message>
        <source>Code va&amp;lid for:</source>
        <translation>Código vá&amp;lido durante:</translation>
    </message>
    <message>
        <source>Code valid for</source>
        <translation>Código válido durante</translation>
    </message>
    <message>
        <source>1 hour</source>
        <translation>1 hora</translation>
    </message>
    <message>
        <source>1 day</source>
        <translation>1 día</translation>
    </message>
    <message>
        <source>7 days</source>
        <translation>7 días</translation>
    </message>
    <message>
        <source>30 days</source>
        <translation>30 días</translation>
    </message>
    <message>
        <source>This patient has no home account yet. An administrator adds one (Administration, Accounts); then make an enrolment code here.</source>
        <translation>Este paciente aún no tiene cuenta doméstica. Un administrador la crea (Administración, Cuentas); después genere aquí un código de registro.</translation>
    </message>
    <message>
        <source>Make enrolment &amp;code</source>
        <translation>Generar &amp;código de registro</translation>
    </message>
    <message>
        <source>A one-time code the patient types on their home computer to connect it to the clinic</source>
        <translation>Un código de un solo uso que el paciente escribe en su ordenador de casa para conectarlo con la clínica</translation>
    </message>
    <message>
        <source>Enrolment code</source>
        <translation>Código de registro</translation>
    </message>
    <message>
        <source>Cop&amp;y code</source>
        <translation>Cop&amp;iar código</translation>
    </message>
    <message>
        <source>Enrolled &amp;devices:</source>
        <translation>&amp;Dispositivos registrados:</translation>
    </message>
    <message>
        <source>Enrolled devices</source>
        <translation>Dispositivos registrados</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>Act&amp;ualizar</translation>
    </message>
    <message>
        <source>Read the devices again (a patient may have enrolled meanwhile)</source>
        <translation>Volver a leer los dispositivos (un paciente puede haberse registrado entretanto)</translation>
    </message>
    <message>
        <source>Re&amp;voke device...</source>
        <translation>Re&amp;vocar dispositivo...</translation>
    </message>
    <message>
        <source>Only therapists and administrators may make enrolment codes and see or revoke home devices. Ask one of them.</source>
        <translation>Solo terapeutas y administradores pueden generar códigos de registro y ver o revocar dispositivos domésticos. Pida ayuda a uno de ellos.</translation>
    </message>
    <message>
        <source>%1 (disabled)</source>
        <translation>%1 (desactivada)</translation>
    </message>
    <message>
        <source>Making the code...</source>
        <translation>Generando el código...</translation>
    </message>
    <message>
        <source>For %1, once, until %2. The patient types it when their home computer asks to connect to the clinic.</source>
        <translation>Para %1, una sola vez, hasta %2. El paciente lo escribe cuando su ordenador de casa pide conectarse con la clínica.</translation>
    </message>
    <message>
        <source>For %1, once, until %2. The patient types it, with the server address %3, when their home computer asks to connect to the clinic.</source>
        <translation>Para %1, una sola vez, hasta %2. El paciente lo escribe, con la dirección del servidor %3, cuando su ordenador de casa pide conectarse con la clínica.</translation>
    </message>
    <message>
        <source>Revoke device</source>
        <translation>Revocar dispositivo</translation>
    </message>
    <message>
        <source>Revoke the device &quot;%1&quot; of %2? It can no longer send sessions or fetch the programme; to use it again the patient enrols it with a new code. Sessions it sent stay.</source>
        <translation>¿Revocar el dispositivo «%1» de %2? Ya no podrá enviar sesiones ni recibir el programa; para volver a usarlo, el paciente lo registra con un código nuevo. Las sesiones ya enviadas se conservan.</translation>
    </message>
    <message>
        <source>Re&amp;voke</source>
        <translation>Re&amp;vocar</translation>
    </message>
    <message>
        <source>The device &quot;%1&quot; is revoked.</source>
        <translation>El dispositivo «%1» está revocado.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::JobProgress</name>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Stopping...</source>
        <translation>Deteniendo...</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MainWindow</name>
    <message>
        <source>Signed-in account</source>
        <translation>Cuenta en uso</translation>
    </message>
    <message>
        <source>&amp;ArmTrack</source>
        <translation>&amp;ArmTrack</translation>
    </message>
    <message>
        <source>&amp;Patients</source>
        <translation>&amp;Pacientes</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation>&amp;Ajustes...</translation>
    </message>
    <message>
        <source>Ctrl+,</source>
        <translation>Ctrl+,</translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation>&amp;Salir de la cuenta</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>&amp;Guía de usuario</translation>
    </message>
    <message>
        <source>&amp;About ArmTrack</source>
        <translation>A&amp;cerca de ArmTrack</translation>
    </message>
    <message>
        <source>About ArmTrack</source>
        <translation>Acerca de ArmTrack</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;ArmTrack %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Measures the shoulder&apos;s and elbow&apos;s joint angles from two wearable IMUs and a Kinect or webcam, for upper-limb rehabilitation.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;ArmTrack %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Mide los ángulos articulares del hombro y del codo con dos IMU portátiles y una Kinect o una webcam, para la rehabilitación del miembro superior.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Signed in as %1</source>
        <translation>Cuenta: %1</translation>
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
        <translation>A&amp;dministración...</translation>
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
        <translation>Mensaje</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::MessageScreen</name>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>Progress</source>
        <translation>Progreso</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::NewSessionScreen</name>
    <message>
        <source>New session</source>
        <translation>Nueva sesión</translation>
    </message>
    <message>
        <source>&amp;Start the live session</source>
        <translation>&amp;Iniciar la sesión en directo</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Dispositivos</translation>
    </message>
    <message>
        <source>Choose the sensors and their options, then check the connection: every stream should turn green and the angles move with the arm.</source>
        <translation>Elija los sensores y sus opciones y compruebe la conexión: cada flujo de datos debe ponerse en verde y los ángulos deben moverse con el brazo.</translation>
    </message>
    <message>
        <source>Sensor calibration</source>
        <translation>Calibración de los sensores</translation>
    </message>
    <message>
        <source>The patient holds and makes the movements shown; ArmTrack then works out how the sensors sit on the arm. About a minute.</source>
        <translation>El paciente mantiene las posiciones y hace los movimientos indicados; ArmTrack calcula después cómo están colocados los sensores en el brazo. Aproximadamente un minuto.</translation>
    </message>
    <message>
        <source>Skip the calibration (the measured segment lengths are used)</source>
        <translation>Omitir la calibración (se usan las longitudes de los segmentos medidas)</translation>
    </message>
    <message>
        <source>Camera calibration</source>
        <translation>Calibración de la cámara</translation>
    </message>
    <message>
        <source>Hold the printed chessboard in front of the webcam in different places and angles until the grid is covered.</source>
        <translation>Sostenga el tablero de ajedrez impreso delante de la webcam en distintos lugares y ángulos hasta cubrir la cuadrícula.</translation>
    </message>
    <message>
        <source>Skip the camera calibration (use the camera&apos;s stored model)</source>
        <translation>Omitir la calibración de la cámara (usar el modelo guardado de la cámara)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::OutputsPanel</name>
    <message>
        <source>&amp;PDF report...</source>
        <translation>Informe &amp;PDF...</translation>
    </message>
    <message>
        <source>The session report: details, metrics, plots, repetitions</source>
        <translation>El informe de la sesión: datos, métricas, gráficas, repeticiones</translation>
    </message>
    <message>
        <source>C&amp;SV...</source>
        <translation>C&amp;SV...</translation>
    </message>
    <message>
        <source>Angles (deg) with their uncertainty, and a metrics table</source>
        <translation>Ángulos (°) con su incertidumbre y una tabla de métricas</translation>
    </message>
    <message>
        <source>Open&amp;Sim .mot...</source>
        <translation>Open&amp;Sim .mot...</translation>
    </message>
    <message>
        <source>The clinical angles as an OpenSim motion file</source>
        <translation>Los ángulos clínicos como archivo de movimiento de OpenSim</translation>
    </message>
    <message>
        <source>&amp;BIDS...</source>
        <translation>&amp;BIDS...</translation>
    </message>
    <message>
        <source>A BIDS motion data set: IMUs, optical data and angles</source>
        <translation>Un conjunto de datos de movimiento BIDS: IMU, datos ópticos y ángulos</translation>
    </message>
    <message>
        <source>Rec&amp;ording...</source>
        <translation>&amp;Grabación...</translation>
    </message>
    <message>
        <source>The raw recording in the open format, bit for bit</source>
        <translation>La grabación en bruto en el formato abierto, bit a bit</translation>
    </message>
    <message>
        <source>Last output</source>
        <translation>Última salida</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientDialog</name>
    <message>
        <source>New patient</source>
        <translation>Nuevo paciente</translation>
    </message>
    <message>
        <source>Edit patient %1</source>
        <translation>Editar el paciente %1</translation>
    </message>
    <message>
        <source>Upper arm length</source>
        <translation>Longitud del brazo</translation>
    </message>
    <message>
        <source>Forearm length</source>
        <translation>Longitud del antebrazo</translation>
    </message>
    <message>
        <source>Upper-arm IMU distance from the shoulder</source>
        <translation>Distancia de la IMU del brazo al hombro</translation>
    </message>
    <message>
        <source>Forearm IMU distance from the elbow</source>
        <translation>Distancia de la IMU del antebrazo al codo</translation>
    </message>
    <message>
        <source>Patient code</source>
        <translation>Código del paciente</translation>
    </message>
    <message>
        <source>e.g. P001</source>
        <translation>p. ej. P001</translation>
    </message>
    <message>
        <source>Patient name</source>
        <translation>Nombre del paciente</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>sin indicar</translation>
    </message>
    <message>
        <source>Sex</source>
        <translation>Sexo</translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation>Lado afectado</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnóstico</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notas</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Paciente</translation>
    </message>
    <message>
        <source>&amp;Code:</source>
        <translation>&amp;Código:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>&amp;Born:</source>
        <translation>&amp;Nacimiento:</translation>
    </message>
    <message>
        <source>&amp;Sex:</source>
        <translation>&amp;Sexo:</translation>
    </message>
    <message>
        <source>Affected &amp;side:</source>
        <translation>&amp;Lado afectado:</translation>
    </message>
    <message>
        <source>&amp;Diagnosis:</source>
        <translation>&amp;Diagnóstico:</translation>
    </message>
    <message>
        <source>Measured segment lengths</source>
        <translation>Longitudes de los segmentos medidas</translation>
    </message>
    <message>
        <source>&amp;Upper arm (shoulder to elbow):</source>
        <translation>&amp;Brazo (hombro a codo):</translation>
    </message>
    <message>
        <source>&amp;Forearm (elbow to wrist):</source>
        <translation>&amp;Antebrazo (codo a muñeca):</translation>
    </message>
    <message>
        <source>Upper-arm IMU from the shoulder:</source>
        <translation>IMU del brazo desde el hombro:</translation>
    </message>
    <message>
        <source>Forearm IMU from the elbow:</source>
        <translation>IMU del antebrazo desde el codo:</translation>
    </message>
    <message>
        <source>N&amp;otes</source>
        <translation>N&amp;otas</translation>
    </message>
    <message>
        <source>Saving...</source>
        <translation>Guardando...</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>sin medir</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientListScreen</name>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Abrir</translation>
    </message>
    <message>
        <source>&amp;New patient...</source>
        <translation>&amp;Nuevo paciente...</translation>
    </message>
    <message>
        <source>&amp;Edit...</source>
        <translation>&amp;Editar...</translation>
    </message>
    <message>
        <source>Patients</source>
        <translation>Pacientes</translation>
    </message>
    <message>
        <source>&amp;Search:</source>
        <translation>&amp;Buscar:</translation>
    </message>
    <message>
        <source>code, name, diagnosis...</source>
        <translation>código, nombre, diagnóstico...</translation>
    </message>
    <message>
        <source>Search patients</source>
        <translation>Buscar pacientes</translation>
    </message>
    <message>
        <source>Patient list</source>
        <translation>Lista de pacientes</translation>
    </message>
    <message>
        <source>Add a patient (%1)</source>
        <translation>Añadir un paciente (%1)</translation>
    </message>
    <message>
        <source>Loading the patients...</source>
        <translation>Cargando los pacientes...</translation>
    </message>
    <message>
        <source>No patients yet. Add the first with &quot;New patient&quot;.</source>
        <translation>Todavía no hay pacientes. Añada el primero con «Nuevo paciente».</translation>
    </message>
    <message>
        <source>No patients.</source>
        <translation>No hay pacientes.</translation>
    </message>
    <message>
        <source>The patients could not be read: %1</source>
        <translation>No se pudieron leer los pacientes: %1</translation>
    </message>
    <message>
        <source>A patient with the code %1 exists already. Choose another code, or cancel and open that patient from the list.</source>
        <translation>Ya existe un paciente con el código %1. Elija otro código o cancele y abra ese paciente desde la lista.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientRecords</name>
    <message>
        <source>Give the patient a code, e.g. P001: it names the patient in files and exports.</source>
        <translation>Dé un código al paciente, p. ej. P001: identifica al paciente en archivos y exportaciones.</translation>
    </message>
    <message>
        <source>The code may hold letters, digits, &apos;-&apos; and &apos;_&apos; (at most 32, starting with a letter or digit): &quot;%1&quot; does not.</source>
        <translation>El código puede contener letras, dígitos, «-» y «_» (32 como máximo, empezando por una letra o un dígito): «%1» no lo cumple.</translation>
    </message>
    <message>
        <source>Give the patient&apos;s name.</source>
        <translation>Indique el nombre del paciente.</translation>
    </message>
    <message>
        <source>The birth date is not a date.</source>
        <translation>La fecha de nacimiento no es una fecha.</translation>
    </message>
    <message>
        <source>The birth date lies in the future.</source>
        <translation>La fecha de nacimiento está en el futuro.</translation>
    </message>
    <message>
        <source>The birth date is before 1900.</source>
        <translation>La fecha de nacimiento es anterior a 1900.</translation>
    </message>
    <message>
        <source>upper arm length</source>
        <translation>Longitud del brazo</translation>
    </message>
    <message>
        <source>forearm length</source>
        <translation>Longitud del antebrazo</translation>
    </message>
    <message>
        <source>upper-arm IMU distance</source>
        <translation>Distancia de la IMU del brazo</translation>
    </message>
    <message>
        <source>forearm IMU distance</source>
        <translation>Distancia de la IMU del antebrazo</translation>
    </message>
    <message>
        <source>The upper-arm IMU sits farther from the shoulder than the elbow is: check both measurements.</source>
        <translation>La IMU del brazo está más lejos del hombro que el codo: revise las dos mediciones.</translation>
    </message>
    <message>
        <source>The forearm IMU sits farther from the elbow than the wrist is: check both measurements.</source>
        <translation>La IMU del antebrazo está más lejos del codo que la muñeca: revise las dos mediciones.</translation>
    </message>
    <message>
        <source>The %1 of %L2 cm is outside %L3-%L4 cm: check the measurement.</source>
        <translation>%1: %L2 cm está fuera del intervalo %L3–%L4 cm; revise la medición.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientScreen</name>
    <message>
        <source>&amp;New session...</source>
        <translation>&amp;Nueva sesión...</translation>
    </message>
    <message>
        <source>&amp;Review session</source>
        <translation>&amp;Revisar la sesión</translation>
    </message>
    <message>
        <source>&amp;Progress report (PDF)...</source>
        <translation>Informe de e&amp;volución (PDF)...</translation>
    </message>
    <message>
        <source>&amp;Edit patient...</source>
        <translation>&amp;Editar el paciente...</translation>
    </message>
    <message>
        <source>&amp;Back to patients</source>
        <translation>&amp;Volver a los pacientes</translation>
    </message>
    <message>
        <source>Patient %1</source>
        <translation>Paciente %1</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Datos</translation>
    </message>
    <message>
        <source>Code:</source>
        <translation>Código:</translation>
    </message>
    <message>
        <source>Born:</source>
        <translation>Nacimiento:</translation>
    </message>
    <message>
        <source>Sex:</source>
        <translation>Sexo:</translation>
    </message>
    <message>
        <source>Affected side:</source>
        <translation>Lado afectado:</translation>
    </message>
    <message>
        <source>Diagnosis:</source>
        <translation>Diagnóstico:</translation>
    </message>
    <message>
        <source>Notes:</source>
        <translation>Notas:</translation>
    </message>
    <message>
        <source>Measured segment lengths</source>
        <translation>Longitudes de los segmentos medidas</translation>
    </message>
    <message>
        <source>Upper arm:</source>
        <translation>Brazo:</translation>
    </message>
    <message>
        <source>Forearm:</source>
        <translation>Antebrazo:</translation>
    </message>
    <message>
        <source>Upper-arm IMU:</source>
        <translation>IMU del brazo:</translation>
    </message>
    <message>
        <source>Forearm IMU:</source>
        <translation>IMU del antebrazo:</translation>
    </message>
    <message>
        <source>Home programme</source>
        <translation>Programa en casa</translation>
    </message>
    <message>
        <source>Progress</source>
        <translation>Progreso</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sesiones</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>Loading...</source>
        <translation>Cargando...</translation>
    </message>
    <message>
        <source>This patient could not be read: %1</source>
        <translation>No se pudo leer este paciente: %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>sin medir</translation>
    </message>
    <message numerus="yes">
        <source>%n stored length(s) could not be read.</source>
        <translation>
            <numerusform>No se pudo leer %n longitud guardada.</numerusform>
            <numerusform>No se pudieron leer %n longitudes guardadas.</numerusform>
        </translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protocolo</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Per week</source>
        <translation>Por semana</translation>
    </message>
    <message>
        <source>Save the progress report</source>
        <translation>Guardar el informe de evolución</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>Archivos PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Writing the progress report...</source>
        <translation>Escribiendo el informe de evolución...</translation>
    </message>
    <message numerus="yes">
        <source>Progress report written: %1 (%n page(s)).</source>
        <translation>
            <numerusform>Informe de evolución escrito: %1 (%n página).</numerusform>
            <numerusform>Informe de evolución escrito: %1 (%n páginas).</numerusform>
        </translation>
    </message>
    <message>
        <source>The progress report could not be written: %1. Choose another folder or file name and try again.</source>
        <translation>No se pudo escribir el informe de evolución: %1. Elija otra carpeta u otro nombre de archivo y vuelva a intentarlo.</translation>
    </message>
    <message>
        <source>%L1 cm</source>
        <translation>%L1 cm</translation>
    </message>
    <message>
        <source>Record a new session with this patient (%1)</source>
        <translation>Grabar una nueva sesión con este paciente (%1)</translation>
    </message>
    <message>
        <source>Target (°)</source>
        <translation>Objetivo (°)</translation>
    </message>
    <message>
        <source>Sets</source>
        <translation>Series</translation>
    </message>
    <message>
        <source>Rest</source>
        <translation>Descanso</translation>
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
        <translation>%1 (las más antiguas primero)</translation>
    </message>
    <message>
        <source>%1 (newest first)</source>
        <translation>%1 (las más recientes primero)</translation>
    </message>
    <message>
        <source>&amp;Delete session...</source>
        <translation>&amp;Eliminar sesión...</translation>
    </message>
    <message>
        <source>(%1)</source>
        <translation>(%1)</translation>
    </message>
    <message>
        <source>session %1</source>
        <translation>sesión %1</translation>
    </message>
    <message>
        <source>the session of %1 (%2, %3, session %4)</source>
        <translation>la sesión del %1 (%2, %3, sesión %4)</translation>
    </message>
    <message>
        <source>free movement</source>
        <translation>movimiento libre</translation>
    </message>
    <message>
        <source>Delete session</source>
        <translation>Eliminar sesión</translation>
    </message>
    <message>
        <source>Delete %1 of %2? Its recording, angles and metrics are removed for good; the audit log keeps that you did it.</source>
        <translation>¿Eliminar %1 de %2? Su grabación, ángulos y métricas se borran para siempre; el registro de auditoría guarda que lo hizo usted.</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Eliminar</translation>
    </message>
    <message>
        <source>Session %1 deleted.</source>
        <translation>Sesión %1 eliminada.</translation>
    </message>
    <message>
        <source>The session could not be deleted: %1</source>
        <translation>No se pudo eliminar la sesión: %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientTableModel</name>
    <message>
        <source>female</source>
        <translation>femenino</translation>
    </message>
    <message>
        <source>male</source>
        <translation>masculino</translation>
    </message>
    <message>
        <source>diverse</source>
        <translation>diverso</translation>
    </message>
    <message>
        <source>left</source>
        <translation>izquierdo</translation>
    </message>
    <message>
        <source>right</source>
        <translation>derecho</translation>
    </message>
    <message>
        <source>both</source>
        <translation>ambos</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Código</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Born</source>
        <translation>Nacimiento</translation>
    </message>
    <message>
        <source>Sex</source>
        <translation>Sexo</translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation>Lado afectado</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnóstico</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ProgressChart</name>
    <message>
        <source>Progress chart</source>
        <translation>Gráfica de evolución</translation>
    </message>
    <message>
        <source>Progress values</source>
        <translation>Valores de la evolución</translation>
    </message>
    <message>
        <source>rad</source>
        <translation>rad</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Fecha</translation>
    </message>
    <message>
        <source>Of normal</source>
        <translation>Del normal</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sesiones</translation>
    </message>
    <message>
        <source>%1: no analysed session yet</source>
        <translation>%1: todavía no hay ninguna sesión analizada</translation>
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
        <translation>d MMM</translation>
    </message>
    <message>
        <source>Largest (%1)</source>
        <translation>Máximo (%1)</translation>
    </message>
    <message>
        <source>Largest angle reached</source>
        <translation>Ángulo máximo alcanzado</translation>
    </message>
    <message>
        <source>Largest angle (%1)</source>
        <translation>Ángulo máximo (%1)</translation>
    </message>
    <message>
        <source>&amp;Motion:</source>
        <translation>&amp;Movimiento:</translation>
    </message>
    <message>
        <source>Motion shown in the progress chart</source>
        <translation>Movimiento mostrado en la gráfica de evolución</translation>
    </message>
    <message>
        <source>The largest angle reached per session in the chosen motion, against date; the table beside it holds the same values.</source>
        <translation>El mayor ángulo alcanzado en cada sesión en el movimiento elegido, frente a la fecha; la tabla de al lado contiene los mismos valores.</translation>
    </message>
    <message>
        <source>Shoulder extension</source>
        <translation>Extensión de hombro</translation>
    </message>
    <message>
        <source>Shoulder external rotation</source>
        <translation>Rotación externa de hombro</translation>
    </message>
    <message>
        <source>Forearm supination</source>
        <translation>Supinación del antebrazo</translation>
    </message>
    <message>
        <source>%1, opposite direction</source>
        <translation>%1, sentido opuesto</translation>
    </message>
    <message>
        <source>Shoulder flexion</source>
        <translation>Flexión de hombro</translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation>Abducción de hombro</translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation>Rotación interna de hombro</translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation>Flexión de codo</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation>Pronación del antebrazo</translation>
    </message>
    <message>
        <source>Normal (%1) %L2 %3</source>
        <translation>Normal (%1) %L2 %3</translation>
    </message>
    <message>
        <source>Trunk flexion (compensation)</source>
        <translation>Flexión del tronco (compensación)</translation>
    </message>
    <message>
        <source>Largest trunk flexion (%1)</source>
        <translation>Flexión máxima del tronco (%1)</translation>
    </message>
    <message>
        <source>Largest trunk flexion</source>
        <translation>Flexión máxima del tronco</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RecordsRecordingTarget</name>
    <message>
        <source>the records of patient %1</source>
        <translation>el historial del paciente %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RecordsService</name>
    <message>
        <source>The background connection to the records could not sign in (%1). Reports, exports and analyses will fail until you sign in again.</source>
        <translation>La conexión en segundo plano con los registros clínicos no pudo acceder (%1). Los informes, las exportaciones y los análisis fallarán hasta que vuelva a entrar.</translation>
    </message>
    <message>
        <source>an unexpected error</source>
        <translation>un error inesperado</translation>
    </message>
    <message>
        <source>cannot create the folder %1: choose a folder you may write to</source>
        <translation>no se puede crear la carpeta %1: elija una carpeta en la que pueda escribir</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ReestimatePanel</name>
    <message>
        <source>Fuse the &amp;optical data (Kinect, webcam)</source>
        <translation>Fusionar los datos ó&amp;pticos (Kinect, webcam)</translation>
    </message>
    <message>
        <source>B&amp;rowse...</source>
        <translation>E&amp;xaminar...</translation>
    </message>
    <message>
        <source>Re-&amp;estimate</source>
        <translation>Re&amp;calcular</translation>
    </message>
    <message>
        <source>Shown:</source>
        <translation>Mostrado:</translation>
    </message>
    <message>
        <source>EKF (extended Kalman filter)</source>
        <translation>EKF (filtro de Kalman extendido)</translation>
    </message>
    <message>
        <source>UKF (unscented Kalman filter)</source>
        <translation>UKF (filtro de Kalman sin aroma)</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filtro</translation>
    </message>
    <message>
        <source>&amp;Filter:</source>
        <translation>&amp;Filtro:</translation>
    </message>
    <message>
        <source>A: body acceleration modelled</source>
        <translation>A: aceleración corporal modelada</translation>
    </message>
    <message>
        <source>B: body acceleration as states</source>
        <translation>B: aceleración corporal como estados</translation>
    </message>
    <message>
        <source>C: no compensation</source>
        <translation>C: sin compensación</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Método</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>&amp;Método:</translation>
    </message>
    <message>
        <source>none (a file from armtrack-cli calibrate)</source>
        <translation>ninguna (un archivo de armtrack-cli calibrate)</translation>
    </message>
    <message>
        <source>Calibration file</source>
        <translation>Archivo de calibración</translation>
    </message>
    <message>
        <source>&amp;Calibration:</source>
        <translation>&amp;Calibración:</translation>
    </message>
    <message>
        <source>Calibrations (*.json)</source>
        <translation>Calibraciones (*.json)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::RepetitionTableModel</name>
    <message>
        <source>partial</source>
        <translation>parcial</translation>
    </message>
    <message>
        <source>full</source>
        <translation>completa</translation>
    </message>
    <message>
        <source>#</source>
        <translation>N.º</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>Inicio (s)</translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation>Fin (s)</translation>
    </message>
    <message>
        <source>Excursion (rad)</source>
        <translation>Excursión (rad)</translation>
    </message>
    <message>
        <source>Range (rad)</source>
        <translation>Rango (rad)</translation>
    </message>
    <message>
        <source>Peak velocity (rad/s)</source>
        <translation>Velocidad máxima (rad/s)</translation>
    </message>
    <message>
        <source>SPARC</source>
        <translation>SPARC</translation>
    </message>
    <message>
        <source>Full or partial</source>
        <translation>Completa o parcial</translation>
    </message>
    <message>
        <source>Excursion (°)</source>
        <translation>Excursión (°)</translation>
    </message>
    <message>
        <source>Range (°)</source>
        <translation>Rango (°)</translation>
    </message>
    <message>
        <source>Peak velocity (°/s)</source>
        <translation>Velocidad máxima (°/s)</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>no medido</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sí</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <source>Trunk flexion (rad)</source>
        <translation>Flexión del tronco (rad)</translation>
    </message>
    <message>
        <source>Trunk flexion (°)</source>
        <translation>Flexión del tronco (°)</translation>
    </message>
    <message>
        <source>Lateral bending (rad)</source>
        <translation>Inclinación lateral (rad)</translation>
    </message>
    <message>
        <source>Lateral bending (°)</source>
        <translation>Inclinación lateral (°)</translation>
    </message>
    <message>
        <source>Axial rotation (rad)</source>
        <translation>Rotación axial (rad)</translation>
    </message>
    <message>
        <source>Axial rotation (°)</source>
        <translation>Rotación axial (°)</translation>
    </message>
    <message>
        <source>Shoulder displacement (cm)</source>
        <translation>Desplazamiento del hombro (cm)</translation>
    </message>
    <message>
        <source>Trunk compensation</source>
        <translation>Compensación del tronco</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ReviewScreen</name>
    <message>
        <source>Review of session %1</source>
        <translation>Revisión de la sesión %1</translation>
    </message>
    <message>
        <source>Session %1</source>
        <translation>Sesión %1</translation>
    </message>
    <message>
        <source>&amp;Back to the patient</source>
        <translation>&amp;Volver al paciente</translation>
    </message>
    <message>
        <source>3D arm replay</source>
        <translation>Reproducción 3D del brazo</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Reproducir</translation>
    </message>
    <message>
        <source>Replay time</source>
        <translation>Tiempo de reproducción</translation>
    </message>
    <message>
        <source>Replay speed</source>
        <translation>Velocidad de reproducción</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Repeticiones</translation>
    </message>
    <message>
        <source>&amp;Repetitions</source>
        <translation>Re&amp;peticiones</translation>
    </message>
    <message>
        <source>Session to compare with</source>
        <translation>Sesión con la que comparar</translation>
    </message>
    <message>
        <source>Another session of this patient, drawn dashed on the plots and as a translucent arm:</source>
        <translation>Otra sesión de este paciente, dibujada con línea discontinua en las gráficas y como brazo translúcido:</translation>
    </message>
    <message>
        <source>Co&amp;mpare</source>
        <translation>Co&amp;mparar</translation>
    </message>
    <message>
        <source>Session notes</source>
        <translation>Notas de la sesión</translation>
    </message>
    <message>
        <source>Sa&amp;ve notes</source>
        <translation>&amp;Guardar las notas</translation>
    </message>
    <message>
        <source>&amp;Notes</source>
        <translation>&amp;Notas</translation>
    </message>
    <message>
        <source>Re-es&amp;timate</source>
        <translation>Re&amp;calcular</translation>
    </message>
    <message>
        <source>Report and e&amp;xport</source>
        <translation>Informe y e&amp;xportación</translation>
    </message>
    <message>
        <source>Reading the session...</source>
        <translation>Leyendo la sesión...</translation>
    </message>
    <message>
        <source>This session could not be read: %1</source>
        <translation>No se pudo leer esta sesión: %1</translation>
    </message>
    <message>
        <source>left arm</source>
        <translation>brazo izquierdo</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>brazo derecho</translation>
    </message>
    <message>
        <source>%1: session of %2, %3</source>
        <translation>%1: sesión del %2, %3</translation>
    </message>
    <message>
        <source>Review: %1, %2</source>
        <translation>Revisión: %1, %2</translation>
    </message>
    <message>
        <source>not analysed yet</source>
        <translation>todavía sin analizar</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) could not be read.</source>
        <translation>
            <numerusform>No se pudo leer %n repetición.</numerusform>
            <numerusform>No se pudieron leer %n repeticiones.</numerusform>
        </translation>
    </message>
    <message>
        <source>No metrics yet.</source>
        <translation>Todavía no hay métricas.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ninguna)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Notes typed earlier were not saved; they are back in the Notes tab. Save them or edit them.</source>
        <translation>Las notas escritas antes no se guardaron; vuelven a estar en la pestaña «Notas». Guárdelas o edítelas.</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <source>Session %1 has no analysis to compare with. Review it and re-estimate it first.</source>
        <translation>La sesión %1 no tiene análisis con el que comparar. Revísela y recalcúlela primero.</translation>
    </message>
    <message>
        <source>That session could not be read: %1</source>
        <translation>No se pudo leer esa sesión: %1</translation>
    </message>
    <message>
        <source>Notes saved.</source>
        <translation>Notas guardadas.</translation>
    </message>
    <message>
        <source>The notes could not be saved: %1. They stay here and in a draft; try again.</source>
        <translation>No se pudieron guardar las notas: %1. Se quedan aquí y en un borrador; vuelva a intentarlo.</translation>
    </message>
    <message>
        <source>Estimating the joint angles again...</source>
        <translation>Recalculando los ángulos articulares...</translation>
    </message>
    <message>
        <source>Re-estimation cancelled; nothing was stored.</source>
        <translation>Recálculo cancelado; no se guardó nada.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <source>New estimates stored as version %1.</source>
        <translation>Nuevos cálculos guardados como versión %1.</translation>
    </message>
    <message>
        <source>The session could not be estimated again: %1. The earlier estimates are kept.</source>
        <translation>No se pudo recalcular la sesión: %1. Se conservan los cálculos anteriores.</translation>
    </message>
    <message>
        <source>Save the session report</source>
        <translation>Guardar el informe de la sesión</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>Archivos PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Folder of the BIDS data set</source>
        <translation>Carpeta del conjunto de datos BIDS</translation>
    </message>
    <message>
        <source>Export as OpenSim motion</source>
        <translation>Exportar como movimiento de OpenSim</translation>
    </message>
    <message>
        <source>OpenSim motion (*.mot)</source>
        <translation>Movimiento de OpenSim (*.mot)</translation>
    </message>
    <message>
        <source>Export the angles as CSV</source>
        <translation>Exportar los ángulos como CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export the recording</source>
        <translation>Exportar la grabación</translation>
    </message>
    <message>
        <source>Recordings (*.csv)</source>
        <translation>Grabaciones (*.csv)</translation>
    </message>
    <message>
        <source>the session report</source>
        <translation>el informe de la sesión</translation>
    </message>
    <message numerus="yes">
        <source>Session report written: %1 (%n page(s)).</source>
        <translation>
            <numerusform>Informe de la sesión escrito: %1 (%n página).</numerusform>
            <numerusform>Informe de la sesión escrito: %1 (%n páginas).</numerusform>
        </translation>
    </message>
    <message>
        <source>the export</source>
        <translation>la exportación</translation>
    </message>
    <message>
        <source>Exported: %1.</source>
        <translation>Exportado: %1.</translation>
    </message>
    <message>
        <source>Writing %1...</source>
        <translation>Escribiendo %1...</translation>
    </message>
    <message>
        <source>%1 could not be written: %2. Choose another place and try again.</source>
        <translation>No se pudo escribir %1: %2. Elija otro lugar y vuelva a intentarlo.</translation>
    </message>
    <message>
        <source>version %1 of %2: %3, method %4</source>
        <translation>versión %1 de %2: %3, método %4</translation>
    </message>
    <message>
        <source>, optical data fused</source>
        <translation>, con datos ópticos fusionados</translation>
    </message>
    <message>
        <source>, no optical data fused</source>
        <translation>, sin datos ópticos fusionados</translation>
    </message>
    <message>
        <source>, calibrated</source>
        <translation>, calibrado</translation>
    </message>
    <message>
        <source>Play or pause the replay (%1)</source>
        <translation>Reproducir o pausar la reproducción (%1)</translation>
    </message>
    <message>
        <source>%L1×</source>
        <translation>%L1×</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) on %1 (%2 full, %3 partial). Smoothness: SPARC %4, LDLJ %5.</source>
        <translation>
            <numerusform>%n repetición de %1 (%2 completas, %3 parciales). Suavidad: SPARC %4, LDLJ %5.</numerusform>
            <numerusform>%n repeticiones de %1 (%2 completas, %3 parciales). Suavidad: SPARC %4, LDLJ %5.</numerusform>
        </translation>
    </message>
    <message>
        <source>This session is waiting for its analysis, which ArmTrack runs in the background while a therapist is signed in: open the review again in a moment, or open &quot;Re-estimate&quot; to analyse it now.</source>
        <translation>Esta sesión espera su análisis, que ArmTrack realiza en segundo plano mientras un terapeuta tiene la sesión iniciada: vuelva a abrir la revisión en un momento o abra «Recalcular» para analizarla ahora.</translation>
    </message>
    <message>
        <source>This session could not be analysed: %1. Open &quot;Re-estimate&quot; to try again, for example with other filter settings.</source>
        <translation>No se pudo analizar esta sesión: %1. Abra «Recalcular» para intentarlo de nuevo, por ejemplo con otros ajustes del filtro.</translation>
    </message>
    <message>
        <source>no reason was stored</source>
        <translation>no se guardó ningún motivo</translation>
    </message>
    <message>
        <source>This recording was cut short, so it was not analysed. Open &quot;Re-estimate&quot; to estimate its joint angles from what was recorded.</source>
        <translation>Esta grabación se interrumpió, por lo que no se analizó. Abra «Recalcular» para estimar sus ángulos articulares a partir de lo grabado.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SessionSetupPage</name>
    <message>
        <source>&amp;Left arm</source>
        <translation>Brazo &amp;izquierdo</translation>
    </message>
    <message>
        <source>&amp;Right arm</source>
        <translation>Brazo &amp;derecho</translation>
    </message>
    <message>
        <source>Patient, protocol and arm</source>
        <translation>Paciente, protocolo y brazo</translation>
    </message>
    <message>
        <source>Choose what this session trains and which arm wears the sensors.</source>
        <translation>Elija qué entrena esta sesión y en qué brazo van los sensores.</translation>
    </message>
    <message>
        <source>Patient:</source>
        <translation>Paciente:</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protocolo</translation>
    </message>
    <message>
        <source>(no protocol: free movement)</source>
        <translation>(sin protocolo: movimiento libre)</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protocolo:</translation>
    </message>
    <message>
        <source>Left arm</source>
        <translation>Brazo izquierdo</translation>
    </message>
    <message>
        <source>Right arm</source>
        <translation>Brazo derecho</translation>
    </message>
    <message>
        <source>Arm:</source>
        <translation>Brazo:</translation>
    </message>
    <message>
        <source>Reading the patient and the protocols...</source>
        <translation>Leyendo el paciente y los protocolos...</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>The patient or the protocols could not be read: %1. Go back and try again.</source>
        <translation>No se pudieron leer el paciente o los protocolos: %1. Vuelva atrás e inténtelo de nuevo.</translation>
    </message>
    <message>
        <source>Note: this protocol is meant for the %1 arm.</source>
        <translation>Nota: este protocolo está pensado para el brazo %1.</translation>
    </message>
    <message>
        <source>left</source>
        <translation>izquierdo</translation>
    </message>
    <message>
        <source>right</source>
        <translation>derecho</translation>
    </message>
    <message numerus="yes">
        <source>Trains %1, target %L2–%L3°, %n repetition(s).</source>
        <translation>
            <numerusform>Entrena %1, objetivo %L2–%L3°, %n repetición.</numerusform>
            <numerusform>Entrena %1, objetivo %L2–%L3°, %n repeticiones.</numerusform>
        </translation>
    </message>
    <message>
        <source>No protocols are stored yet: an administrator adds them under ArmTrack &gt; Administration &gt; Protocols. Without one the session records free movement.</source>
        <translation>Aún no hay protocolos guardados: un administrador los añade en ArmTrack &gt; Administración &gt; Protocolos. Sin protocolo, la sesión graba movimiento libre.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SessionTableModel</name>
    <message>
        <source>complete</source>
        <translation>completa</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>interrumpida</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>grabando</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ninguna)</translation>
    </message>
    <message>
        <source>Started</source>
        <translation>Inicio</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protocolo</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Duración</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>IMU samples</source>
        <translation>Muestras de IMU</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notas</translation>
    </message>
    <message>
        <source>home</source>
        <translation>en casa</translation>
    </message>
    <message>
        <source>clinic</source>
        <translation>consulta</translation>
    </message>
    <message>
        <source>%L1 of %L2 repetitions</source>
        <translation>%L1 de %L2 repeticiones</translation>
    </message>
    <message>
        <source>%L1 of %L2 sets (not measured)</source>
        <translation>%L1 de %L2 series (sin medir)</translation>
    </message>
    <message>
        <source>reached %L1° of %L2°</source>
        <translation>alcanzó %L1° de %L2°</translation>
    </message>
    <message>
        <source>pain %L1/10</source>
        <translation>dolor %L1/10</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Lugar</translation>
    </message>
    <message>
        <source>Patient&apos;s own account</source>
        <translation>Lo que dice el paciente</translation>
    </message>
    <message>
        <source>complete, analysis pending</source>
        <translation>completa, análisis pendiente</translation>
    </message>
    <message>
        <source>%1, cannot be analysed</source>
        <translation>%1, no se puede analizar</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SettingsDialog</name>
    <message>
        <source>&amp;Add folder...</source>
        <translation>&amp;Añadir carpeta...</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Quitar</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Ajustes</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Pantalla</translation>
    </message>
    <message>
        <source>degrees</source>
        <translation>grados</translation>
    </message>
    <message>
        <source>radians</source>
        <translation>radianes</translation>
    </message>
    <message>
        <source>Angle units</source>
        <translation>Unidad de los ángulos</translation>
    </message>
    <message>
        <source>Angle &amp;units:</source>
        <translation>&amp;Unidad de los ángulos:</translation>
    </message>
    <message>
        <source>as the system</source>
        <translation>como el sistema</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Idioma:</translation>
    </message>
    <message>
        <source>light</source>
        <translation>claro</translation>
    </message>
    <message>
        <source>dark</source>
        <translation>oscuro</translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation>Apariencia</translation>
    </message>
    <message>
        <source>A&amp;ppearance:</source>
        <translation>A&amp;pariencia:</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>Datos</translation>
    </message>
    <message>
        <source>Data folder</source>
        <translation>Carpeta de datos</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Examinar...</translation>
    </message>
    <message>
        <source>Data &amp;folder:</source>
        <translation>&amp;Carpeta de datos:</translation>
    </message>
    <message>
        <source>armtrack.db in the data folder</source>
        <translation>armtrack.db en la carpeta de datos</translation>
    </message>
    <message>
        <source>A file path, sqlite:PATH, or postgresql://user@host:port/dbname</source>
        <translation>Una ruta de archivo, sqlite:RUTA o postgresql://usuario@host:puerto/nombrebd</translation>
    </message>
    <message>
        <source>Database</source>
        <translation>Base de datos</translation>
    </message>
    <message>
        <source>&amp;Database:</source>
        <translation>&amp;Base de datos:</translation>
    </message>
    <message>
        <source>Device plugin folders (searched before the built-in ones)</source>
        <translation>Carpetas de complementos de dispositivos (se buscan antes que las incorporadas)</translation>
    </message>
    <message>
        <source>Plugin folders</source>
        <translation>Carpetas de complementos</translation>
    </message>
    <message>
        <source>Estimation of new sessions</source>
        <translation>Cálculo de las sesiones nuevas</translation>
    </message>
    <message>
        <source>EKF (extended Kalman filter)</source>
        <translation>EKF (filtro de Kalman extendido)</translation>
    </message>
    <message>
        <source>UKF (unscented Kalman filter)</source>
        <translation>UKF (filtro de Kalman sin aroma)</translation>
    </message>
    <message>
        <source>Default filter</source>
        <translation>Filtro predeterminado</translation>
    </message>
    <message>
        <source>F&amp;ilter:</source>
        <translation>F&amp;iltro:</translation>
    </message>
    <message>
        <source>A: body acceleration modelled</source>
        <translation>A: aceleración corporal modelada</translation>
    </message>
    <message>
        <source>B: body acceleration as states</source>
        <translation>B: aceleración corporal como estados</translation>
    </message>
    <message>
        <source>C: no compensation</source>
        <translation>C: sin compensación</translation>
    </message>
    <message>
        <source>Default method</source>
        <translation>Método predeterminado</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>&amp;Método:</translation>
    </message>
    <message>
        <source>Plugin folder</source>
        <translation>Carpeta de complementos</translation>
    </message>
    <message>
        <source>Give the data folder as a full path, e.g. %1.</source>
        <translation>Indique la carpeta de datos con su ruta completa, p. ej. %1.</translation>
    </message>
    <message>
        <source>The database location is not one ArmTrack understands: %1</source>
        <translation>ArmTrack no entiende esta ubicación de la base de datos: %1</translation>
    </message>
    <message>
        <source>The plugin folder %1 does not exist.</source>
        <translation>La carpeta de complementos %1 no existe.</translation>
    </message>
    <message>
        <source>https://NAME:PORT (optional)</source>
        <translation>https://NOMBRE:PUERTO (opcional)</translation>
    </message>
    <message>
        <source>The clinic&apos;s sync server as patients type it on their home computer; shown with each enrolment code</source>
        <translation>El servidor de sincronización de la clínica tal como los pacientes lo escriben en su ordenador de casa; se muestra con cada código de registro</translation>
    </message>
    <message>
        <source>Sync server address</source>
        <translation>Dirección del servidor de sincronización</translation>
    </message>
    <message>
        <source>S&amp;ync server address:</source>
        <translation>Servidor de sincroni&amp;zación:</translation>
    </message>
    <message>
        <source>Give the sync server address as https://NAME:PORT, e.g. https://sync.clinic.example:8443, or leave it empty.</source>
        <translation>Indique la dirección del servidor de sincronización como https://NOMBRE:PUERTO, p. ej. https://sync.clinic.example:8443, o déjela vacía.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SignInScreen</name>
    <message>
        <source>&amp;Sign in</source>
        <translation>&amp;Entrar</translation>
    </message>
    <message>
        <source>Sign in</source>
        <translation>Acceso</translation>
    </message>
    <message>
        <source>Sign in to ArmTrack</source>
        <translation>Acceder a ArmTrack</translation>
    </message>
    <message>
        <source>Records: %1</source>
        <translation>Registros clínicos: %1</translation>
    </message>
    <message>
        <source>Account name</source>
        <translation>Nombre de la cuenta</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Contraseña</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Contraseña:</translation>
    </message>
    <message>
        <source>Type your account name.</source>
        <translation>Escriba el nombre de su cuenta.</translation>
    </message>
    <message>
        <source>Type your password.</source>
        <translation>Escriba su contraseña.</translation>
    </message>
    <message>
        <source>Signing in...</source>
        <translation>Entrando...</translation>
    </message>
    <message>
        <source>Check the name and the password (is Caps Lock on?) and try again. If you have forgotten it, an administrator can set a new one.</source>
        <translation>Compruebe el nombre y la contraseña (¿está activado Bloq Mayús?) y vuelva a intentarlo. Si la ha olvidado, un administrador puede asignarle una nueva.</translation>
    </message>
    <message numerus="yes">
        <source>Wait %n s</source>
        <translation>
            <numerusform>Espere %n s</numerusform>
            <numerusform>Espere %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Too many wrong passwords for this account: wait %n s, then try again.</source>
        <translation>
            <numerusform>Demasiadas contraseñas incorrectas para esta cuenta: espere %n segundo y vuelva a intentarlo.</numerusform>
            <numerusform>Demasiadas contraseñas incorrectas para esta cuenta: espere %n segundos y vuelva a intentarlo.</numerusform>
        </translation>
    </message>
    <message>
        <source>Wrong user name or password.</source>
        <translation>Nombre de usuario o contraseña incorrectos.</translation>
    </message>
    <message>
        <source>Too many wrong passwords for this account. You may try again now.</source>
        <translation>Demasiadas contraseñas incorrectas para esta cuenta. Ya puede volver a intentarlo.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::TrunkPanel</name>
    <message>
        <source>Trunk</source>
        <translation>Tronco</translation>
    </message>
    <message>
        <source>Largest trunk flexion:</source>
        <translation>Flexión máxima del tronco:</translation>
    </message>
    <message>
        <source>Largest lateral bending:</source>
        <translation>Inclinación lateral máxima:</translation>
    </message>
    <message>
        <source>Largest axial rotation:</source>
        <translation>Rotación axial máxima:</translation>
    </message>
    <message>
        <source>Largest shoulder displacement:</source>
        <translation>Desplazamiento máximo del hombro:</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>no medido</translation>
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
        <translation>Repeticiones con compensación:</translation>
    </message>
    <message>
        <source>%1 of %2 (flexion over %3)</source>
        <translation>%1 de %2 (flexión por encima de %3)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::AccountDialog</name>
    <message>
        <source>Password</source>
        <translation>Contraseña</translation>
    </message>
    <message>
        <source>Password again</source>
        <translation>Repetir contraseña</translation>
    </message>
    <message>
        <source>New account</source>
        <translation>Cuenta nueva</translation>
    </message>
    <message>
        <source>Account name</source>
        <translation>Nombre de la cuenta</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Función</translation>
    </message>
    <message>
        <source>Patient of the home account</source>
        <translation>Paciente de la cuenta en casa</translation>
    </message>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>&amp;Role:</source>
        <translation>&amp;Función:</translation>
    </message>
    <message>
        <source>Pa&amp;tient (home account):</source>
        <translation>Pa&amp;ciente (cuenta en casa):</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Contraseña:</translation>
    </message>
    <message>
        <source>Password &amp;again:</source>
        <translation>Repetir c&amp;ontraseña:</translation>
    </message>
    <message>
        <source>Give the account a name, e.g. the person&apos;s first name and initial.</source>
        <translation>Dé un nombre a la cuenta, p. ej. el nombre de pila y la inicial de la persona.</translation>
    </message>
    <message>
        <source>A home account belongs to one patient: add the patient first, then choose them.</source>
        <translation>Una cuenta en casa pertenece a un paciente: añada primero el paciente y luego elíjalo.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::AccountsPage</name>
    <message>
        <source>Accounts</source>
        <translation>Cuentas</translation>
    </message>
    <message>
        <source>&amp;Add account...</source>
        <translation>&amp;Añadir cuenta...</translation>
    </message>
    <message>
        <source>Reset &amp;password...</source>
        <translation>Restablecer &amp;contraseña...</translation>
    </message>
    <message>
        <source>Re&amp;move account...</source>
        <translation>&amp;Quitar cuenta...</translation>
    </message>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Función</translation>
    </message>
    <message>
        <source>Patient (home accounts)</source>
        <translation>Paciente (cuentas en casa)</translation>
    </message>
    <message>
        <source>Account %1 (%2) added: they can sign in now.</source>
        <translation>Cuenta %1 (%2) añadida: ya puede iniciar sesión.</translation>
    </message>
    <message>
        <source>Choose the account whose password to reset.</source>
        <translation>Elija la cuenta cuya contraseña quiere restablecer.</translation>
    </message>
    <message>
        <source>The password of %1 is reset. Tell them the new one in person.</source>
        <translation>La contraseña de %1 se ha restablecido. Comunique la nueva en persona.</translation>
    </message>
    <message>
        <source>Choose the account to remove.</source>
        <translation>Elija la cuenta que quiere quitar.</translation>
    </message>
    <message>
        <source>Remove account</source>
        <translation>Quitar cuenta</translation>
    </message>
    <message>
        <source>Remove the account %1? They can no longer sign in. The sessions they recorded stay.</source>
        <translation>¿Quitar la cuenta %1? Ya no podrá iniciar sesión. Las sesiones que grabó se conservan.</translation>
    </message>
    <message>
        <source>Account %1 removed.</source>
        <translation>Cuenta %1 quitada.</translation>
    </message>
    <message>
        <source>&amp;Enable account</source>
        <translation>&amp;Habilitar cuenta</translation>
    </message>
    <message>
        <source>D&amp;isable account...</source>
        <translation>&amp;Deshabilitar cuenta...</translation>
    </message>
    <message>
        <source>Disabled</source>
        <translation>Deshabilitada</translation>
    </message>
    <message>
        <source>Active</source>
        <translation>Activa</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Choose the account to disable or enable.</source>
        <translation>Elija la cuenta que desea deshabilitar o habilitar.</translation>
    </message>
    <message>
        <source>Account %1 disabled: it can no longer sign in. Its sessions and history keep its name.</source>
        <translation>Cuenta %1 deshabilitada: ya no puede iniciar sesión. Sus sesiones y su historial conservan su nombre.</translation>
    </message>
    <message>
        <source>Account %1 enabled: it can sign in again.</source>
        <translation>Cuenta %1 habilitada: puede volver a iniciar sesión.</translation>
    </message>
    <message>
        <source>Disable account</source>
        <translation>Deshabilitar cuenta</translation>
    </message>
    <message>
        <source>Disable the account %1? It can no longer sign in until an administrator enables it again. Its sessions and history stay, under its name.</source>
        <translation>¿Deshabilitar la cuenta %1? No podrá iniciar sesión hasta que un administrador la habilite de nuevo. Sus sesiones y su historial se conservan, con su nombre.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::AdminScreen</name>
    <message>
        <source>Administration</source>
        <translation>Administración</translation>
    </message>
    <message>
        <source>&amp;Accounts</source>
        <translation>&amp;Cuentas</translation>
    </message>
    <message>
        <source>P&amp;rotocols</source>
        <translation>P&amp;rotocolos</translation>
    </message>
    <message>
        <source>&amp;Home programmes</source>
        <translation>Programas en &amp;casa</translation>
    </message>
    <message>
        <source>Back to the patients</source>
        <translation>Volver a los pacientes</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ExerciseDialog</name>
    <message>
        <source>Its own &amp;target range</source>
        <translation>Su propio rango &amp;objetivo</translation>
    </message>
    <message>
        <source>Target from</source>
        <translation>Objetivo desde</translation>
    </message>
    <message>
        <source>Target to</source>
        <translation>Objetivo hasta</translation>
    </message>
    <message>
        <source>Edit exercise %1</source>
        <translation>Editar ejercicio %1</translation>
    </message>
    <message>
        <source>New exercise</source>
        <translation>Ejercicio nuevo</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protocolo</translation>
    </message>
    <message>
        <source>Sets</source>
        <translation>Series</translation>
    </message>
    <message>
        <source>Repetitions per set</source>
        <translation>Repeticiones por serie</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Rest between sets</source>
        <translation>Descanso entre series</translation>
    </message>
    <message>
        <source>Sessions per week</source>
        <translation>Sesiones por semana</translation>
    </message>
    <message>
        <source>Notes for the patient</source>
        <translation>Notas para el paciente</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protocolo:</translation>
    </message>
    <message>
        <source>S&amp;ets:</source>
        <translation>S&amp;eries:</translation>
    </message>
    <message>
        <source>&amp;Repetitions per set:</source>
        <translation>&amp;Repeticiones por serie:</translation>
    </message>
    <message>
        <source>Target &amp;from:</source>
        <translation>Objetivo &amp;desde:</translation>
    </message>
    <message>
        <source>Target &amp;to:</source>
        <translation>Objetivo &amp;hasta:</translation>
    </message>
    <message>
        <source>Re&amp;st between sets:</source>
        <translation>Des&amp;canso entre series:</translation>
    </message>
    <message>
        <source>Sessions per &amp;week:</source>
        <translation>Sesiones por se&amp;mana:</translation>
    </message>
    <message>
        <source>&amp;Notes:</source>
        <translation>&amp;Notas:</translation>
    </message>
    <message>
        <source>the protocol&apos;s (%1)</source>
        <translation>las del protocolo (%1)</translation>
    </message>
    <message>
        <source>the protocol&apos;s</source>
        <translation>las del protocolo</translation>
    </message>
    <message>
        <source>There is no protocol yet: add one on the Protocols page first.</source>
        <translation>Aún no hay ningún protocolo: añada uno primero en la página Protocolos.</translation>
    </message>
    <message>
        <source>The target ends below where it starts: make &quot;to&quot; at least &quot;from&quot;.</source>
        <translation>El objetivo termina por debajo de donde empieza: «hasta» debe ser al menos «desde».</translation>
    </message>
    <message>
        <source>Tr&amp;unk limit:</source>
        <translation>Límite del tron&amp;co:</translation>
    </message>
    <message>
        <source>the protocol&apos;s (%1 deg)</source>
        <translation>la del protocolo (%1°)</translation>
    </message>
    <message>
        <source>the protocol&apos;s (off)</source>
        <translation>la del protocolo (desactivado)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::FormDialog</name>
    <message>
        <source> deg</source>
        <translation> grados</translation>
    </message>
    <message>
        <source>Choose a password of at least %1 characters.</source>
        <translation>Elija una contraseña de al menos %1 caracteres.</translation>
    </message>
    <message>
        <source>The two passwords differ: type the same password twice.</source>
        <translation>Las dos contraseñas no coinciden: escriba la misma contraseña dos veces.</translation>
    </message>
    <message>
        <source>administrator</source>
        <translation>administrador</translation>
    </message>
    <message>
        <source>therapist</source>
        <translation>terapeuta</translation>
    </message>
    <message>
        <source>home account</source>
        <translation>cuenta en casa</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Saving...</source>
        <translation>Guardando...</translation>
    </message>
    <message>
        <source>Trunk limit</source>
        <translation>Límite del tronco</translation>
    </message>
    <message>
        <source>Degrees of trunk flexion: leaning further, the patient is told &quot;Keep your back against the chair&quot; and the repetition counts as made with compensation. Needs a trunk sensor.</source>
        <translation>Grados de flexión del tronco: si el paciente se inclina más, se le dice «Mantenga la espalda contra la silla» y la repetición cuenta como hecha con compensación. Requiere un sensor de tronco.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::PasswordDialog</name>
    <message>
        <source>New password</source>
        <translation>Contraseña nueva</translation>
    </message>
    <message>
        <source>New password again</source>
        <translation>Repetir la contraseña nueva</translation>
    </message>
    <message>
        <source>New password for %1</source>
        <translation>Contraseña nueva para %1</translation>
    </message>
    <message>
        <source>&amp;New password:</source>
        <translation>Contraseña &amp;nueva:</translation>
    </message>
    <message>
        <source>Password &amp;again:</source>
        <translation>Repetir c&amp;ontraseña:</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ProgrammePage</name>
    <message>
        <source>Pa&amp;tient:</source>
        <translation>Pa&amp;ciente:</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Paciente</translation>
    </message>
    <message>
        <source>Home programme</source>
        <translation>Programa en casa</translation>
    </message>
    <message>
        <source>&amp;Add exercise...</source>
        <translation>&amp;Añadir ejercicio...</translation>
    </message>
    <message>
        <source>&amp;Edit exercise...</source>
        <translation>&amp;Editar ejercicio...</translation>
    </message>
    <message>
        <source>Re&amp;move exercise...</source>
        <translation>&amp;Quitar ejercicio...</translation>
    </message>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>There are no patients yet: add them on the patient list first.</source>
        <translation>Aún no hay pacientes: añádalos primero en la lista de pacientes.</translation>
    </message>
    <message>
        <source>%1 x %2</source>
        <translation>%1 x %2</translation>
    </message>
    <message>
        <source>%1 to %2 deg</source>
        <translation>%1 a %2 grados</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Ejercicio</translation>
    </message>
    <message>
        <source>Sets x repetitions</source>
        <translation>Series x repeticiones</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Objetivo</translation>
    </message>
    <message>
        <source>Rest</source>
        <translation>Descanso</translation>
    </message>
    <message>
        <source>Per week</source>
        <translation>Por semana</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notas</translation>
    </message>
    <message>
        <source>Choose a patient first.</source>
        <translation>Elija primero un paciente.</translation>
    </message>
    <message>
        <source>Choose the exercise to edit.</source>
        <translation>Elija el ejercicio que quiere editar.</translation>
    </message>
    <message>
        <source>There is no protocol yet: add one on the Protocols page first.</source>
        <translation>Aún no hay ningún protocolo: añada uno primero en la página Protocolos.</translation>
    </message>
    <message>
        <source>%1 is in the home programme of %2.</source>
        <translation>%1 está en el programa en casa de %2.</translation>
    </message>
    <message>
        <source>Choose the exercise to remove.</source>
        <translation>Elija el ejercicio que quiere quitar.</translation>
    </message>
    <message>
        <source>Remove exercise</source>
        <translation>Quitar ejercicio</translation>
    </message>
    <message>
        <source>Remove %1 from the home programme of %2? The sessions already done stay.</source>
        <translation>¿Quitar %1 del programa en casa de %2? Las sesiones ya hechas se conservan.</translation>
    </message>
    <message>
        <source>%1 removed from the programme.</source>
        <translation>%1 quitado del programa.</translation>
    </message>
    <message>
        <source>%1 deg</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>off</source>
        <translation>desactivado</translation>
    </message>
    <message>
        <source>Trunk limit</source>
        <translation>Límite del tronco</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ProtocolDialog</name>
    <message>
        <source>Target from</source>
        <translation>Objetivo desde</translation>
    </message>
    <message>
        <source>Target to</source>
        <translation>Objetivo hasta</translation>
    </message>
    <message>
        <source>New protocol</source>
        <translation>Protocolo nuevo</translation>
    </message>
    <message>
        <source>Edit protocol %1</source>
        <translation>Editar protocolo %1</translation>
    </message>
    <message>
        <source>Protocol name</source>
        <translation>Nombre del protocolo</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Repeticiones</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Lado</translation>
    </message>
    <message>
        <source>either arm</source>
        <translation>cualquier brazo</translation>
    </message>
    <message>
        <source>left arm</source>
        <translation>brazo izquierdo</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>brazo derecho</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>&amp;Angle:</source>
        <translation>Á&amp;ngulo:</translation>
    </message>
    <message>
        <source>Target &amp;from:</source>
        <translation>Objetivo &amp;desde:</translation>
    </message>
    <message>
        <source>Target &amp;to:</source>
        <translation>Objetivo &amp;hasta:</translation>
    </message>
    <message>
        <source>&amp;Repetitions:</source>
        <translation>&amp;Repeticiones:</translation>
    </message>
    <message>
        <source>&amp;Side:</source>
        <translation>&amp;Lado:</translation>
    </message>
    <message>
        <source>Give the protocol a name, e.g. &quot;Shoulder flexion to 120&quot;.</source>
        <translation>Dé un nombre al protocolo, p. ej. «Flexión de hombro hasta 120».</translation>
    </message>
    <message>
        <source>The target ends below where it starts: make &quot;to&quot; at least &quot;from&quot;.</source>
        <translation>El objetivo termina por debajo de donde empieza: «hasta» debe ser al menos «desde».</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Desactivado</translation>
    </message>
    <message>
        <source>Tr&amp;unk limit:</source>
        <translation>Límite del tron&amp;co:</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::admin::ProtocolsPage</name>
    <message>
        <source>left arm</source>
        <translation>brazo izquierdo</translation>
    </message>
    <message>
        <source>right arm</source>
        <translation>brazo derecho</translation>
    </message>
    <message>
        <source>either arm</source>
        <translation>cualquier brazo</translation>
    </message>
    <message>
        <source>Protocols</source>
        <translation>Protocolos</translation>
    </message>
    <message>
        <source>&amp;Add protocol...</source>
        <translation>&amp;Añadir protocolo...</translation>
    </message>
    <message>
        <source>&amp;Edit protocol...</source>
        <translation>&amp;Editar protocolo...</translation>
    </message>
    <message>
        <source>%1 to %2 deg</source>
        <translation>%1 a %2 grados</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Objetivo</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Repeticiones</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Lado</translation>
    </message>
    <message>
        <source>Choose the protocol to edit.</source>
        <translation>Elija el protocolo que quiere editar.</translation>
    </message>
    <message>
        <source>Protocol %1 added: it is offered in new sessions and programmes.</source>
        <translation>Protocolo %1 añadido: se ofrece en las sesiones y programas nuevos.</translation>
    </message>
    <message>
        <source>Protocol %1 saved.</source>
        <translation>Protocolo %1 guardado.</translation>
    </message>
    <message>
        <source>%1 deg</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>off</source>
        <translation>desactivado</translation>
    </message>
    <message>
        <source>Trunk limit</source>
        <translation>Límite del tronco</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::ExerciseRecording</name>
    <message>
        <source>the records</source>
        <translation>el registro clínico</translation>
    </message>
    <message>
        <source>This exercise cannot be saved: %1</source>
        <translation>Este ejercicio no se puede guardar: %1</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::ExerciseScreen</name>
    <message>
        <source>The sensors could not start: %1. Check that they are switched on; you can skip this exercise.</source>
        <translation>Los sensores no pudieron arrancar: %1. Compruebe que están encendidos; puede saltarse este ejercicio.</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Ejercicio</translation>
    </message>
    <message>
        <source>Exercise %L1 of %L2: %3</source>
        <translation>Ejercicio %L1 de %L2: %3</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Instrucción</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Repeticiones</translation>
    </message>
    <message>
        <source>Your angle now</source>
        <translation>Su ángulo ahora</translation>
    </message>
    <message>
        <source>Feedback</source>
        <translation>Indicaciones</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <source>Pause (Escape)</source>
        <translation>Pausa (Esc)</translation>
    </message>
    <message>
        <source>S&amp;kip this exercise</source>
        <translation>Sa&amp;ltar este ejercicio</translation>
    </message>
    <message>
        <source>S&amp;top for today</source>
        <translation>&amp;Terminar por hoy</translation>
    </message>
    <message>
        <source>%1: not measured</source>
        <translation>%1: sin medir</translation>
    </message>
    <message>
        <source>Raise your arm forward with the elbow straight, up to where the light arm goes, then lower it slowly.</source>
        <translation>Levante el brazo hacia delante con el codo estirado, hasta donde llega el brazo claro, y bájelo despacio.</translation>
    </message>
    <message>
        <source>Raise your arm out to the side with the elbow straight, up to where the light arm goes, then lower it slowly.</source>
        <translation>Levante el brazo hacia el lado con el codo estirado, hasta donde llega el brazo claro, y bájelo despacio.</translation>
    </message>
    <message>
        <source>Keep your elbow at your side, bent at a right angle. Turn your hand in towards your belly and out again, as the light arm does.</source>
        <translation>Mantenga el codo junto al cuerpo, doblado en ángulo recto. Gire la mano hacia el vientre y de nuevo hacia fuera, como el brazo claro.</translation>
    </message>
    <message>
        <source>Bend your elbow up as far as the light arm goes, then straighten it slowly. Keep your upper arm still.</source>
        <translation>Doble el codo hasta donde llega el brazo claro y estírelo despacio. Mantenga quieto el brazo.</translation>
    </message>
    <message>
        <source>Keep your elbow bent at a right angle. Turn your palm down and up again, as the light arm does.</source>
        <translation>Mantenga el codo doblado en ángulo recto. Gire la palma hacia abajo y de nuevo hacia arriba, como el brazo claro.</translation>
    </message>
    <message numerus="yes">
        <source>Then press Start: %n set(s) of %1 repetitions.</source>
        <translation>
            <numerusform>Después pulse Empezar: %n serie de %1 repeticiones.</numerusform>
            <numerusform>Después pulse Empezar: %n series de %1 repeticiones.</numerusform>
        </translation>
    </message>
    <message>
        <source>ArmTrack cannot measure this exercise without the camera. Do it as shown and count the repetitions yourself; it is recorded for your therapist.</source>
        <translation>Sin la cámara, ArmTrack no puede medir este ejercicio. Hágalo como se muestra y cuente usted las repeticiones; se graba para su terapeuta.</translation>
    </message>
    <message>
        <source>Your therapist says: %1</source>
        <translation>Su terapeuta dice: %1</translation>
    </message>
    <message>
        <source>&amp;Start set %1</source>
        <translation>&amp;Empezar la serie %1</translation>
    </message>
    <message>
        <source>Set %1 of %2: move like the light arm, %3 times. Take your time.</source>
        <translation>Serie %1 de %2: muévase como el brazo claro, %3 veces. Tómese su tiempo.</translation>
    </message>
    <message>
        <source>Set %1 of %2: do the movement %3 times, then press Done.</source>
        <translation>Serie %1 de %2: haga el movimiento %3 veces y pulse Hecho.</translation>
    </message>
    <message>
        <source>&amp;Done with this set</source>
        <translation>Serie &amp;hecha</translation>
    </message>
    <message>
        <source>&amp;Start the next set now</source>
        <translation>&amp;Empezar ya la siguiente serie</translation>
    </message>
    <message>
        <source>Paused. Press Go on when you are ready.</source>
        <translation>En pausa. Pulse Seguir cuando esté listo.</translation>
    </message>
    <message>
        <source>&amp;Go on</source>
        <translation>&amp;Seguir</translation>
    </message>
    <message>
        <source>Saving this exercise…</source>
        <translation>Guardando este ejercicio…</translation>
    </message>
    <message>
        <source>Rest: %1 s</source>
        <translation>Descanso: %1 s</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 de %2</translation>
    </message>
    <message>
        <source>Count: %1 times</source>
        <translation>Cuente: %1 veces</translation>
    </message>
    <message>
        <source>Set %1 of %2</source>
        <translation>Serie %1 de %2</translation>
    </message>
    <message>
        <source>Set %1 done. Well done!</source>
        <translation>Serie %1 hecha. ¡Muy bien!</translation>
    </message>
    <message>
        <source>The camera does not see you, so ArmTrack cannot measure this shoulder exercise now. Go on as shown, count yourself, and press Done after each set.</source>
        <translation>La cámara no le ve, así que ArmTrack no puede medir ahora este ejercicio de hombro. Siga como se muestra, cuente usted y pulse Hecho después de cada serie.</translation>
    </message>
    <message>
        <source>%1: %2°</source>
        <translation>%1: %2°</translation>
    </message>
    <message>
        <source>Target reached!</source>
        <translation>¡Objetivo alcanzado!</translation>
    </message>
    <message>
        <source>Good: %1 done.</source>
        <translation>Bien: %1 hechas.</translation>
    </message>
    <message>
        <source>Try to go a little further next time.</source>
        <translation>Intente llegar un poco más lejos la próxima vez.</translation>
    </message>
    <message>
        <source>Almost: go a little further for it to count.</source>
        <translation>Casi: llegue un poco más lejos para que cuente.</translation>
    </message>
    <message>
        <source>A little slower, please.</source>
        <translation>Un poco más despacio, por favor.</translation>
    </message>
    <message>
        <source>Keep your elbow straight; move only your shoulder.</source>
        <translation>Mantenga el codo estirado; mueva solo el hombro.</translation>
    </message>
    <message>
        <source>Keep your upper arm still; move only your elbow and forearm.</source>
        <translation>Mantenga quieto el brazo; mueva solo el codo y el antebrazo.</translation>
    </message>
    <message>
        <source>Trunk cue</source>
        <translation>Aviso del tronco</translation>
    </message>
    <message>
        <source>Repetitions leaning too far</source>
        <translation>Repeticiones inclinándose demasiado</translation>
    </message>
    <message>
        <source>Keep your back against the chair</source>
        <translation>Mantenga la espalda contra la silla</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) leaning too far</source>
        <translation>
            <numerusform>%n repetición inclinándose demasiado</numerusform>
            <numerusform>%n repeticiones inclinándose demasiado</numerusform>
        </translation>
    </message>
    <message>
        <source>Rest with your upper arm hanging, your elbow bent at a right angle and your thumb up. The next set starts by itself when the time is up.</source>
        <translation>Descanse con el brazo colgando, el codo doblado en ángulo recto y el pulgar hacia arriba. La siguiente serie empieza sola cuando se acabe el tiempo.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeCalibrationScreen</name>
    <message>
        <source>Now ArmTrack learns how the sensors sit on your arm today. It takes about a minute: press Start, then do what the screen says and what the light arm shows.</source>
        <translation>Ahora ArmTrack aprende cómo están hoy los sensores en su brazo. Tarda un minuto: pulse Empezar y haga lo que dice la pantalla y muestra el brazo claro.</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Calibración</translation>
    </message>
    <message>
        <source>S&amp;kip the calibration</source>
        <translation>Sa&amp;ltar la calibración</translation>
    </message>
    <message>
        <source>&amp;Go on</source>
        <translation>&amp;Seguir</translation>
    </message>
    <message>
        <source>&amp;Go on without it</source>
        <translation>&amp;Seguir sin ella</translation>
    </message>
    <message>
        <source>Skip the calibration?</source>
        <translation>¿Omitir la calibración?</translation>
    </message>
    <message>
        <source>Do you want to go on without the calibration?</source>
        <translation>¿Quiere continuar sin la calibración?</translation>
    </message>
    <message>
        <source>Without it, ArmTrack measures your arm a little less exactly today. The calibration takes about a minute.</source>
        <translation>Sin ella, ArmTrack mide su brazo hoy con algo menos de exactitud. La calibración dura alrededor de un minuto.</translation>
    </message>
    <message>
        <source>&amp;Skip it</source>
        <translation>&amp;Omitirla</translation>
    </message>
    <message>
        <source>&amp;Do the calibration</source>
        <translation>&amp;Hacer la calibración</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeConnectScreen</name>
    <message>
        <source>Connect to the clinic</source>
        <translation>Conectar con la clínica</translation>
    </message>
    <message>
        <source>Your therapist gives you the clinic&apos;s address and a code. Once connected, your sessions are sent to your therapist and your exercises come from the clinic. You can always exercise without a connection: sessions are kept and sent later.</source>
        <translation>Su terapeuta le da la dirección de la clínica y un código. Una vez conectado, sus sesiones se envían a su terapeuta y sus ejercicios llegan de la clínica. Siempre puede hacer ejercicio sin conexión: las sesiones se guardan y se envían más tarde.</translation>
    </message>
    <message>
        <source>Clinic&apos;s &amp;address (for example sync.clinic.example:8443)</source>
        <translation>&amp;Dirección de la clínica (por ejemplo sync.clinic.example:8443)</translation>
    </message>
    <message>
        <source>&amp;Code from your therapist</source>
        <translation>Código de su &amp;terapeuta</translation>
    </message>
    <message>
        <source>Clinic&apos;s address</source>
        <translation>Dirección de la clínica</translation>
    </message>
    <message>
        <source>Code from your therapist</source>
        <translation>Código de su terapeuta</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Conectar</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Volver</translation>
    </message>
    <message>
        <source>Type the clinic&apos;s address and the code, then press Connect.</source>
        <translation>Escriba la dirección de la clínica y el código y pulse «Conectar».</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Conectando…</translation>
    </message>
    <message>
        <source>Not connected to a clinic: sessions are kept on this computer</source>
        <translation>Sin conexión con una clínica: las sesiones se guardan en este ordenador</translation>
    </message>
    <message>
        <source>Sending to the clinic…</source>
        <translation>Enviando a la clínica…</translation>
    </message>
    <message>
        <source>The clinic&apos;s server is not the one connected before: nothing was sent. Sessions are kept; call your therapist.</source>
        <translation>El servidor de la clínica no es el de antes: no se envió nada. Las sesiones se guardan; llame a su terapeuta.</translation>
    </message>
    <message>
        <source>The clinic no longer accepts this computer: sessions are kept. Call your therapist.</source>
        <translation>La clínica ya no acepta este ordenador: las sesiones se guardan. Llame a su terapeuta.</translation>
    </message>
    <message>
        <source>Not connected: sessions are kept and sent later</source>
        <translation>Sin conexión: las sesiones se guardan y se envían más tarde</translation>
    </message>
    <message numerus="yes">
        <source>%n session(s) waiting to be sent</source>
        <translation>
            <numerusform>%n sesión pendiente de envío</numerusform>
            <numerusform>%n sesiones pendientes de envío</numerusform>
        </translation>
    </message>
    <message>
        <source>Everything is sent</source>
        <translation>Todo está enviado</translation>
    </message>
    <message>
        <source>Sent today %1</source>
        <translation>Enviado hoy a las %1</translation>
    </message>
    <message>
        <source>Last sent %1</source>
        <translation>Último envío: %1</translation>
    </message>
    <message>
        <source>Connected to the clinic. Your sessions will be sent there.</source>
        <translation>Conectado con la clínica. Sus sesiones se enviarán allí.</translation>
    </message>
    <message>
        <source>The clinic&apos;s server cannot be reached: check the address and the internet connection, then try again.</source>
        <translation>No se puede contactar con el servidor de la clínica: compruebe la dirección y la conexión a internet y vuelva a intentarlo.</translation>
    </message>
    <message>
        <source>The code is wrong, used or expired: ask your therapist for a new one.</source>
        <translation>El código es incorrecto, ya se usó o ha caducado: pida uno nuevo a su terapeuta.</translation>
    </message>
    <message>
        <source>This computer cannot keep the connection (%1): call your therapist.</source>
        <translation>Este ordenador no puede guardar la conexión (%1): llame a su terapeuta.</translation>
    </message>
    <message>
        <source>The clinic&apos;s server did not accept it (%1): try again, or call your therapist.</source>
        <translation>El servidor de la clínica no lo aceptó (%1): vuelva a intentarlo o llame a su terapeuta.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeController</name>
    <message>
        <source>One moment</source>
        <translation>Un momento</translation>
    </message>
    <message>
        <source>Loading today&apos;s exercises…</source>
        <translation>Cargando los ejercicios de hoy…</translation>
    </message>
    <message>
        <source>Today</source>
        <translation>Hoy</translation>
    </message>
    <message>
        <source>Sensor check</source>
        <translation>Comprobación de los sensores</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Calibración</translation>
    </message>
    <message>
        <source>Exercise %L1 of %L2</source>
        <translation>Ejercicio %L1 de %L2</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Resumen</translation>
    </message>
    <message>
        <source>Something went wrong</source>
        <translation>Algo ha ido mal</translation>
    </message>
    <message>
        <source>%1
Please try again. If this happens again, call your therapist.</source>
        <translation>%1
Inténtelo de nuevo. Si vuelve a pasar, llame a su terapeuta.</translation>
    </message>
    <message>
        <source>&amp;Try again</source>
        <translation>&amp;Reintentar</translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation>Cerrar &amp;sesión</translation>
    </message>
    <message>
        <source>cannot create a temporary folder for the sensor check (%1): free some disk space</source>
        <translation>no se puede crear una carpeta temporal para la comprobación de los sensores (%1): libere espacio en el disco</translation>
    </message>
    <message>
        <source>Stop this exercise?</source>
        <translation>¿Terminar este ejercicio?</translation>
    </message>
    <message>
        <source>Do you want to stop for today?</source>
        <translation>¿Quiere terminar por hoy?</translation>
    </message>
    <message>
        <source>What you have done so far is saved for your therapist. You can also keep exercising.</source>
        <translation>Lo que ha hecho hasta ahora se guarda para su terapeuta. También puede seguir haciendo ejercicio.</translation>
    </message>
    <message>
        <source>&amp;Stop and save</source>
        <translation>&amp;Detener y guardar</translation>
    </message>
    <message>
        <source>&amp;Keep exercising</source>
        <translation>Seguir &amp;ejercitando</translation>
    </message>
    <message>
        <source>Clinic</source>
        <translation>Clínica</translation>
    </message>
    <message>
        <source>home computer</source>
        <translation>ordenador de casa</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeStartScreen</name>
    <message numerus="yes">
        <source>%1: %n set(s) of %2 repetitions, %3 s rest</source>
        <translation>
            <numerusform>%1: %n serie de %2 repeticiones, %3 s de descanso</numerusform>
            <numerusform>%1: %n series de %2 repeticiones, %3 s de descanso</numerusform>
        </translation>
    </message>
    <message>
        <source>Today&apos;s exercises</source>
        <translation>Ejercicios de hoy</translation>
    </message>
    <message>
        <source>Hello, %1</source>
        <translation>Hola, %1</translation>
    </message>
    <message>
        <source>Your therapist has not given you any exercises yet.</source>
        <translation>Su terapeuta aún no le ha dado ejercicios.</translation>
    </message>
    <message>
        <source>Today&apos;s exercises:</source>
        <translation>Ejercicios de hoy:</translation>
    </message>
    <message>
        <source>(not measured without the camera)</source>
        <translation>(sin la cámara no se mide)</translation>
    </message>
    <message>
        <source>What can be measured</source>
        <translation>Qué se puede medir</translation>
    </message>
    <message>
        <source>This set-up has no camera. ArmTrack measures your elbow and forearm well with the two sensors alone. It cannot trust the shoulder&apos;s angles without the camera: they drift slowly about the vertical. Do the shoulder exercises as your therapist showed you; they are recorded for your therapist, but ArmTrack does not count them or show their numbers.%1</source>
        <translation>Este equipo no tiene cámara. ArmTrack mide bien el codo y el antebrazo solo con los dos sensores. Sin la cámara no puede fiarse de los ángulos del hombro: derivan despacio alrededor de la vertical. Haga los ejercicios de hombro como le enseñó su terapeuta; se graban para su terapeuta, pero ArmTrack no los cuenta ni muestra sus números.%1</translation>
    </message>
    <message>
        <source>None of today&apos;s exercises needs it.</source>
        <translation>Ninguno de los ejercicios de hoy la necesita.</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Empezar</translation>
    </message>
    <message>
        <source>Sign &amp;out</source>
        <translation>Cerrar &amp;sesión</translation>
    </message>
    <message>
        <source>I use the keyboard or the mouse</source>
        <translation>Uso el teclado o el ratón</translation>
    </message>
    <message>
        <source>I use one switch: the choices light up in turn</source>
        <translation>Uso un pulsador: las opciones se iluminan por turnos</translation>
    </message>
    <message>
        <source>I use one switch: press to go on</source>
        <translation>Uso un pulsador: pulsar es seguir</translation>
    </message>
    <message>
        <source>How I press: %1</source>
        <translation>Cómo pulso: %1</translation>
    </message>
    <message>
        <source>Press to change how you use ArmTrack</source>
        <translation>Pulse para cambiar cómo usa ArmTrack</translation>
    </message>
    <message>
        <source>C&amp;linic</source>
        <translation>Clí&amp;nica</translation>
    </message>
    <message>
        <source>Connect to the clinic with its address and your therapist&apos;s code</source>
        <translation>Conectar con la clínica con su dirección y el código de su terapeuta</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeStyle</name>
    <message>
        <source>information</source>
        <translation>información</translation>
    </message>
    <message>
        <source>well done</source>
        <translation>muy bien</translation>
    </message>
    <message>
        <source>hint</source>
        <translation>consejo</translation>
    </message>
    <message>
        <source>problem</source>
        <translation>problema</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeSummaryChart</name>
    <message>
        <source>Chart of the range reached</source>
        <translation>Gráfico del rango alcanzado</translation>
    </message>
    <message>
        <source>Last time</source>
        <translation>La última vez</translation>
    </message>
    <message>
        <source>%1 sessions ago</source>
        <translation>hace %1 sesiones</translation>
    </message>
    <message>
        <source>%1 (not measured)</source>
        <translation>%1 (sin medir)</translation>
    </message>
    <message>
        <source>Today</source>
        <translation>Hoy</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Objetivo</translation>
    </message>
    <message>
        <source>Farthest angle reached (degrees)</source>
        <translation>Mayor ángulo alcanzado (grados)</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeSummaryScreen</name>
    <message>
        <source>%1: %L2 of %L3 repetitions</source>
        <translation>%1: %L2 de %L3 repeticiones</translation>
    </message>
    <message>
        <source>%1: %L2 of %L3 sets done (not measured without the camera)</source>
        <translation>%1: %L2 de %L3 series hechas (sin la cámara no se mide)</translation>
    </message>
    <message>
        <source>you reached %L1°, the target is %L2°</source>
        <translation>llegó a %L1°, el objetivo es %L2°</translation>
    </message>
    <message>
        <source>last time %L1°</source>
        <translation>la última vez %L1°</translation>
    </message>
    <message>
        <source>stopped early</source>
        <translation>terminado antes</translation>
    </message>
    <message>
        <source>Saving…</source>
        <translation>Guardando…</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Resumen</translation>
    </message>
    <message>
        <source>Well done, %1!</source>
        <translation>¡Muy bien, %1!</translation>
    </message>
    <message>
        <source>How much pain did you have? 0 is none, 10 the worst.</source>
        <translation>¿Cuánto dolor ha tenido? 0 es ninguno, 10 el peor.</translation>
    </message>
    <message>
        <source>Anything to tell your therapist? (You may leave it empty.)</source>
        <translation>¿Algo que decir a su terapeuta? (Puede dejarlo vacío.)</translation>
    </message>
    <message>
        <source>Less pain</source>
        <translation>Menos dolor</translation>
    </message>
    <message>
        <source>More pain</source>
        <translation>Más dolor</translation>
    </message>
    <message>
        <source>Pain score</source>
        <translation>Nivel de dolor</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>sin respuesta</translation>
    </message>
    <message>
        <source>Your comment</source>
        <translation>Su comentario</translation>
    </message>
    <message>
        <source>Saved</source>
        <translation>Guardado</translation>
    </message>
    <message>
        <source>&amp;Save and finish</source>
        <translation>&amp;Guardar y terminar</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Cerrar</translation>
    </message>
    <message>
        <source>Saved. Your therapist will see it. Thank you!</source>
        <translation>Guardado. Su terapeuta lo verá. ¡Gracias!</translation>
    </message>
    <message>
        <source>It could not be saved: %1. Press Save to try again.</source>
        <translation>No se pudo guardar: %1. Pulse Guardar para intentarlo de nuevo.</translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) leaning too far</source>
        <translation>
            <numerusform>%n repetición inclinándose demasiado</numerusform>
            <numerusform>%n repeticiones inclinándose demasiado</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeWindow</name>
    <message>
        <source>ArmTrack: my exercises</source>
        <translation>ArmTrack: mis ejercicios</translation>
    </message>
    <message>
        <source>My exercises</source>
        <translation>Mis ejercicios</translation>
    </message>
    <message>
        <source>Whose exercises</source>
        <translation>De quién son los ejercicios</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Sending to the clinic</source>
        <translation>Envío a la clínica</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::SensorCheckScreen</name>
    <message>
        <source>&amp;Start the check</source>
        <translation>&amp;Empezar la comprobación</translation>
    </message>
    <message>
        <source>&amp;Go on</source>
        <translation>&amp;Seguir</translation>
    </message>
    <message>
        <source>S&amp;kip the check</source>
        <translation>Sa&amp;ltar la comprobación</translation>
    </message>
    <message>
        <source>The sensors could not be started: %1</source>
        <translation>No se pudieron arrancar los sensores: %1</translation>
    </message>
    <message>
        <source>The check could not be recorded: %1</source>
        <translation>No se pudo grabar la comprobación: %1</translation>
    </message>
    <message>
        <source>no data came from the sensors</source>
        <translation>no llegaron datos de los sensores</translation>
    </message>
    <message>
        <source>Sensor check</source>
        <translation>Comprobación de los sensores</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Instrucción</translation>
    </message>
    <message>
        <source>Result of the check</source>
        <translation>Resultado de la comprobación</translation>
    </message>
    <message>
        <source>&amp;Check again</source>
        <translation>&amp;Comprobar de nuevo</translation>
    </message>
    <message>
        <source>&amp;Go on anyway</source>
        <translation>&amp;Seguir de todos modos</translation>
    </message>
    <message>
        <source>S&amp;top the check</source>
        <translation>&amp;Parar la comprobación</translation>
    </message>
    <message>
        <source>First, a check of the sensors</source>
        <translation>Primero, una comprobación de los sensores</translation>
    </message>
    <message>
        <source>Strap the upper-arm sensor on your upper arm and the forearm sensor on your forearm, each with its arrow pointing up towards your shoulder, as in the picture. Let your arm hang loosely straight down. After Start, keep still for 3 seconds, then bend your elbow up and straighten it again, three times.</source>
        <translation>Sujete el sensor del brazo en el brazo y el del antebrazo en el antebrazo, cada uno con la flecha hacia arriba, hacia el hombro, como en la imagen. Deje el brazo colgando suelto y recto. Después de Empezar, quédese quieto 3 segundos; luego doble el codo y estírelo de nuevo, tres veces.</translation>
    </message>
    <message>
        <source>Starting the sensors…</source>
        <translation>Arrancando los sensores…</translation>
    </message>
    <message>
        <source>Let your arm hang loosely straight down.</source>
        <translation>Deje el brazo colgando suelto y recto.</translation>
    </message>
    <message>
        <source>Keep still: %1</source>
        <translation>Quieto: %1</translation>
    </message>
    <message>
        <source>Let your arm hang loosely straight down, and keep it still.</source>
        <translation>Deje el brazo colgando suelto y recto, y manténgalo quieto.</translation>
    </message>
    <message>
        <source>Bend your elbow: %1 of %2</source>
        <translation>Doble el codo: %1 de %2</translation>
    </message>
    <message>
        <source>Bend your elbow up as far as is comfortable, then straighten it again. Keep your upper arm still.</source>
        <translation>Doble el codo hasta donde le resulte cómodo y estírelo de nuevo. Mantenga quieto el brazo.</translation>
    </message>
    <message>
        <source>Keep still</source>
        <translation>Quieto</translation>
    </message>
    <message>
        <source>Let your arm hang down again.</source>
        <translation>Deje caer el brazo de nuevo.</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>Comprobando…</translation>
    </message>
    <message>
        <source>You can relax your arm.</source>
        <translation>Puede relajar el brazo.</translation>
    </message>
    <message>
        <source>The sensors are right</source>
        <translation>Los sensores están bien</translation>
    </message>
    <message>
        <source>Both sensors are on the right places and the right way round.</source>
        <translation>Los dos sensores están en su sitio y en la posición correcta.</translation>
    </message>
    <message>
        <source>Well done.</source>
        <translation>Muy bien.</translation>
    </message>
    <message>
        <source>Please change the sensors</source>
        <translation>Cambie los sensores, por favor</translation>
    </message>
    <message>
        <source>Please do the check again</source>
        <translation>Haga la comprobación de nuevo, por favor</translation>
    </message>
    <message>
        <source>Change them as in the picture, then press Check again.</source>
        <translation>Cámbielos como en la imagen y pulse Comprobar de nuevo.</translation>
    </message>
    <message>
        <source>Press Check again when you are ready.</source>
        <translation>Pulse Comprobar de nuevo cuando esté listo.</translation>
    </message>
    <message>
        <source>No data came from the upper-arm sensor. Check that it is switched on and charged, then press Check again.</source>
        <translation>No llegaron datos del sensor del brazo. Compruebe que está encendido y cargado, y pulse Comprobar de nuevo.</translation>
    </message>
    <message>
        <source>No data came from the forearm sensor. Check that it is switched on and charged, then press Check again.</source>
        <translation>No llegaron datos del sensor del antebrazo. Compruebe que está encendido y cargado, y pulse Comprobar de nuevo.</translation>
    </message>
    <message>
        <source>Your arm was not still at the start. Let it hang loosely and keep it still until the countdown ends.</source>
        <translation>Su brazo no estaba quieto al principio. Déjelo colgar suelto y quieto hasta que acabe la cuenta atrás.</translation>
    </message>
    <message>
        <source>ArmTrack did not see your elbow bend. When asked, bend your elbow up and straighten it again, three times.</source>
        <translation>ArmTrack no vio doblarse su codo. Cuando se le pida, doble el codo y estírelo de nuevo, tres veces.</translation>
    </message>
    <message>
        <source>Both sensors moved the same way. Keep your upper arm still while you bend the elbow, and check that one sensor is on the upper arm and one on the forearm.</source>
        <translation>Los dos sensores se movieron igual. Mantenga quieto el brazo mientras dobla el codo, y compruebe que un sensor está en el brazo y otro en el antebrazo.</translation>
    </message>
    <message>
        <source>A sensor gives readings that do not make sense. Switch it off and on again; if this happens again, call your therapist.</source>
        <translation>Un sensor da lecturas sin sentido. Apáguelo y vuelva a encenderlo; si vuelve a pasar, llame a su terapeuta.</translation>
    </message>
    <message>
        <source>The two sensors are swapped: the upper-arm sensor is on your forearm, and the forearm sensor is on your upper arm. Put each one on the other&apos;s place.</source>
        <translation>Los dos sensores están intercambiados: el sensor del brazo está en su antebrazo y el del antebrazo en su brazo. Ponga cada uno en el sitio del otro.</translation>
    </message>
    <message>
        <source>The sensor on your upper arm is upside down: its arrow points down. Turn it round so that the arrow points up towards your shoulder.</source>
        <translation>El sensor de su brazo está al revés: su flecha apunta hacia abajo. Gírelo para que la flecha apunte hacia arriba, hacia el hombro.</translation>
    </message>
    <message>
        <source>The sensor on your forearm is upside down: its arrow points down. Turn it round so that the arrow points up towards your shoulder.</source>
        <translation>El sensor de su antebrazo está al revés: su flecha apunta hacia abajo. Gírelo para que la flecha apunte hacia arriba, hacia el hombro.</translation>
    </message>
    <message>
        <source>The sensor on your upper arm sits crooked, or your arm was not hanging straight. Straighten the strap and let your arm hang loosely.</source>
        <translation>El sensor de su brazo está torcido, o su brazo no colgaba recto. Enderece la correa y deje el brazo colgando suelto.</translation>
    </message>
    <message>
        <source>The sensor on your forearm sits crooked, or your elbow was not straight. Straighten the strap and let your arm hang loosely.</source>
        <translation>El sensor de su antebrazo está torcido, o su codo no estaba estirado. Enderece la correa y deje el brazo colgando suelto.</translation>
    </message>
    <message>
        <source>Sit upright with your back against the chair, let your arm hang loosely straight down, and keep still.</source>
        <translation>Siéntese erguido con la espalda contra la silla, deje el brazo colgando suelto y recto hacia abajo y quédese quieto.</translation>
    </message>
    <message>
        <source>All three sensors are on the right places and the right way round.</source>
        <translation>Los tres sensores están en su sitio y en la posición correcta.</translation>
    </message>
    <message>
        <source>No data came from the chest sensor. Check that it is switched on and charged, then press Check again.</source>
        <translation>No llegaron datos del sensor del pecho. Compruebe que esté encendido y cargado y pulse «Comprobar de nuevo».</translation>
    </message>
    <message>
        <source>The chest sensor seems to be on upside down. Turn it the other way up, as your therapist showed you, and sit upright.</source>
        <translation>El sensor del pecho parece estar al revés. Gírelo, como le mostró su terapeuta, y siéntese erguido.</translation>
    </message>
    <message>
        <source>The chest sensor seems to be turned: it sits %1° off. Put it flat on the middle of your breastbone, the way your therapist showed you, and sit upright.</source>
        <translation>El sensor del pecho parece estar girado: está desviado %1°. Colóquelo plano en el centro del esternón, como le mostró su terapeuta, y siéntese erguido.</translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::StrapPicture</name>
    <message>
        <source>How it should be</source>
        <translation>Cómo debe ser</translation>
    </message>
    <message>
        <source>upper-arm sensor</source>
        <translation>sensor del brazo</translation>
    </message>
    <message>
        <source>forearm sensor</source>
        <translation>sensor del antebrazo</translation>
    </message>
    <message>
        <source>The upper-arm sensor on the upper arm and the forearm sensor on the forearm, both with their arrow pointing up towards the shoulder.</source>
        <translation>El sensor del brazo en el brazo y el del antebrazo en el antebrazo, ambos con la flecha hacia arriba, hacia el hombro.</translation>
    </message>
    <message>
        <source>Now the two sensors are on each other&apos;s place.</source>
        <translation>Ahora cada sensor está en el sitio del otro.</translation>
    </message>
    <message>
        <source>Now the sensor on the upper arm has its arrow pointing down.</source>
        <translation>Ahora la flecha del sensor del brazo apunta hacia abajo.</translation>
    </message>
    <message>
        <source>Now the sensor on the forearm has its arrow pointing down.</source>
        <translation>Ahora la flecha del sensor del antebrazo apunta hacia abajo.</translation>
    </message>
    <message>
        <source>Now the sensor on the upper arm sits crooked.</source>
        <translation>Ahora el sensor del brazo está torcido.</translation>
    </message>
    <message>
        <source>Now the sensor on the forearm sits crooked.</source>
        <translation>Ahora el sensor del antebrazo está torcido.</translation>
    </message>
    <message>
        <source>Picture of the sensors on the arm</source>
        <translation>Imagen de los sensores en el brazo</translation>
    </message>
    <message>
        <source>Worn correctly on your left arm</source>
        <translation>Bien colocados en su brazo izquierdo</translation>
    </message>
    <message>
        <source>Worn correctly on your right arm</source>
        <translation>Bien colocados en su brazo derecho</translation>
    </message>
    <message>
        <source>Now, on your left arm</source>
        <translation>Ahora, en su brazo izquierdo</translation>
    </message>
    <message>
        <source>Now, on your right arm</source>
        <translation>Ahora, en su brazo derecho</translation>
    </message>
    <message>
        <source>Your left arm, seen from the side.</source>
        <translation>Su brazo izquierdo, visto de lado.</translation>
    </message>
    <message>
        <source>Your right arm, seen from the side.</source>
        <translation>Su brazo derecho, visto de lado.</translation>
    </message>
</context>
<context>
    <name>armtrack::reports</name>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <source>numbers: repetitions at their peaks (p = partial)</source>
        <translation>números: repeticiones en sus picos (p = parcial)</translation>
    </message>
    <message>
        <source>angle (deg)</source>
        <translation>ángulo (°)</translation>
    </message>
    <message>
        <source>date</source>
        <translation>fecha</translation>
    </message>
    <message>
        <source>not measured in this period</source>
        <translation>no medido en este periodo</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Página %1 de %2</translation>
    </message>
    <message>
        <source>Page %1</source>
        <translation>Página %1</translation>
    </message>
    <message>
        <source>Progress report</source>
        <translation>Informe de evolución</translation>
    </message>
    <message>
        <source>Patient and period</source>
        <translation>Paciente y periodo</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Patient code</source>
        <translation>Código del paciente</translation>
    </message>
    <message>
        <source>Date of birth</source>
        <translation>Fecha de nacimiento</translation>
    </message>
    <message>
        <source>Affected side</source>
        <translation>Lado afectado</translation>
    </message>
    <message>
        <source>Therapist</source>
        <translation>Terapeuta</translation>
    </message>
    <message>
        <source>Sessions</source>
        <translation>Sesiones</translation>
    </message>
    <message>
        <source>Range of motion over time</source>
        <translation>Rango de movimiento a lo largo del tiempo</translation>
    </message>
    <message>
        <source>%1: largest angle reached (deg)</source>
        <translation>%1: mayor ángulo alcanzado (°)</translation>
    </message>
    <message>
        <source>Normal ranges: %1.</source>
        <translation>Rangos normales: %1.</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Fecha</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>N.º</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protocolo</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Duración</translation>
    </message>
    <message>
        <source>Reps</source>
        <translation>Rep.</translation>
    </message>
    <message>
        <source>%1 ROM</source>
        <translation>%1 ROM</translation>
    </message>
    <message>
        <source>ROM in degrees (maximum minus minimum over the session).</source>
        <translation>ROM en grados (máximo menos mínimo de la sesión).</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 a %2</translation>
    </message>
    <message>
        <source>%1 (%2), progress %3</source>
        <translation>%1 (%2), evolución %3</translation>
    </message>
    <message>
        <source>progress report</source>
        <translation>informe de evolución</translation>
    </message>
    <message>
        <source>Progress report: %1, %2</source>
        <translation>Informe de evolución: %1, %2</translation>
    </message>
    <message>
        <source>Shoulder flexion</source>
        <translation>Flexión de hombro</translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation>Abducción de hombro</translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation>Rotación interna de hombro</translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation>Flexión de codo</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation>Pronosupinación</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sí</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <source>left</source>
        <translation>izquierdo</translation>
    </message>
    <message>
        <source>right</source>
        <translation>derecho</translation>
    </message>
    <message>
        <source>both</source>
        <translation>ambos</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>either</source>
        <translation>cualquiera</translation>
    </message>
    <message>
        <source>female</source>
        <translation>femenino</translation>
    </message>
    <message>
        <source>male</source>
        <translation>masculino</translation>
    </message>
    <message>
        <source>diverse</source>
        <translation>diverso</translation>
    </message>
    <message>
        <source>complete</source>
        <translation>completa</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>interrumpida</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>grabando</translation>
    </message>
    <message>
        <source>%1 %2 UTC</source>
        <comment>a date and a time of day</comment>
        <translation>%1 %2 UTC</translation>
    </message>
    <message>
        <source>%1 - %2 - generated %3</source>
        <translation>%1 – %2 – generado el %3</translation>
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
        <translation>(JSON no válido: %1 en la posición %2)</translation>
    </message>
    <message numerus="yes">
        <source>... %n more</source>
        <translation>
            <numerusform>... %n más</numerusform>
            <numerusform>... %n más</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %2, target %3 to %4 deg, %n repetitions</source>
        <translation>
            <numerusform>%1: %2, objetivo de %3 a %4°, %n repetición</numerusform>
            <numerusform>%1: %2, objetivo de %3 a %4°, %n repeticiones</numerusform>
        </translation>
    </message>
    <message>
        <source>Patient and session</source>
        <translation>Paciente y sesión</translation>
    </message>
    <message>
        <source>Sex</source>
        <translation>Sexo</translation>
    </message>
    <message>
        <source>Side measured</source>
        <translation>Lado medido</translation>
    </message>
    <message>
        <source>Session</source>
        <translation>Sesión</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnóstico</translation>
    </message>
    <message>
        <source>Devices and calibration</source>
        <translation>Dispositivos y calibración</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Dispositivos</translation>
    </message>
    <message>
        <source>No devices were recorded for this session.</source>
        <translation>No se registró ningún dispositivo para esta sesión.</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Calibración</translation>
    </message>
    <message>
        <source>%1 not defined</source>
        <translation>%1 no definido</translation>
    </message>
    <message>
        <source>Metrics per clinical angle</source>
        <translation>Métricas por ángulo clínico</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Min (deg)</source>
        <translation>Mín. (°)</translation>
    </message>
    <message>
        <source>Max (deg)</source>
        <translation>Máx. (°)</translation>
    </message>
    <message>
        <source>ROM (deg)</source>
        <translation>ROM (°)</translation>
    </message>
    <message>
        <source>Peak velocity (deg/s)</source>
        <translation>Velocidad máxima (°/s)</translation>
    </message>
    <message>
        <source>Mean velocity (deg/s)</source>
        <translation>Velocidad media (°/s)</translation>
    </message>
    <message>
        <source>Moving time (s)</source>
        <translation>Tiempo en movimiento (s)</translation>
    </message>
    <message>
        <source>Joint angles over time</source>
        <translation>Ángulos articulares a lo largo del tiempo</translation>
    </message>
    <message>
        <source>shaded: protocol target %1 to %2 deg</source>
        <translation>sombreado: objetivo del protocolo de %1 a %2°</translation>
    </message>
    <message>
        <source>%1 (deg)</source>
        <translation>%1 (°)</translation>
    </message>
    <message>
        <source>p</source>
        <comment>a partial repetition&apos;s mark on the plot</comment>
        <translation>p</translation>
    </message>
    <message>
        <source>Repetitions</source>
        <translation>Repeticiones</translation>
    </message>
    <message>
        <source>No repetitions were detected (0 repetitions).</source>
        <translation>No se detectó ninguna repetición (0 repeticiones).</translation>
    </message>
    <message numerus="yes">
        <source>%n repetitions counted on %1: %2 full, %3 partial (judged against a reference range of %4 deg); %5 cut by the start or end of the recording and not counted.</source>
        <translation>
            <numerusform>%n repetición contada en %1: %2 completas, %3 parciales (valoradas frente a un rango de referencia de %4°); %5 cortadas por el inicio o el final de la grabación y no contadas.</numerusform>
            <numerusform>%n repeticiones contadas en %1: %2 completas, %3 parciales (valoradas frente a un rango de referencia de %4°); %5 cortadas por el inicio o el final de la grabación y no contadas.</numerusform>
        </translation>
    </message>
    <message>
        <source>#</source>
        <translation>N.º</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>Inicio (s)</translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation>Fin (s)</translation>
    </message>
    <message>
        <source>ROM of %1 (deg)</source>
        <translation>ROM de %1 (°)</translation>
    </message>
    <message>
        <source>Partial</source>
        <translation>Parcial</translation>
    </message>
    <message>
        <source>Comparison with normative ranges</source>
        <translation>Comparación con los rangos normativos</translation>
    </message>
    <message>
        <source>Comparison with earlier sessions</source>
        <translation>Comparación con sesiones anteriores</translation>
    </message>
    <message>
        <source>Range of motion (deg) of each angle per session.</source>
        <translation>Rango de movimiento (°) de cada ángulo por sesión.</translation>
    </message>
    <message>
        <source>%1 this session</source>
        <translation>%1 esta sesión</translation>
    </message>
    <message>
        <source>Change since last</source>
        <translation>Cambio desde la anterior</translation>
    </message>
    <message>
        <source>Other side, %1</source>
        <translation>Otro lado, %1</translation>
    </message>
    <message>
        <source>No earlier sessions to compare with.</source>
        <translation>No hay sesiones anteriores con las que comparar.</translation>
    </message>
    <message>
        <source>Therapist&apos;s notes</source>
        <translation>Notas del terapeuta</translation>
    </message>
    <message>
        <source>No notes.</source>
        <translation>Sin notas.</translation>
    </message>
    <message>
        <source>%1 (%2), session of %3</source>
        <translation>%1 (%2), sesión del %3</translation>
    </message>
    <message>
        <source>session report</source>
        <translation>informe de la sesión</translation>
    </message>
    <message>
        <source>Session report: %1, %2</source>
        <translation>Informe de la sesión: %1, %2</translation>
    </message>
    <message>
        <source>Session report</source>
        <translation>Informe de la sesión</translation>
    </message>
    <message>
        <source>shaded: AAOS normal range of motion, 0-%1 deg</source>
        <translation>sombreado: rango de movimiento normal según la AAOS, 0–%1°</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 samples used, %2 rows rejected (not finite), %3 gaps. Smoothness of the wrist path: %4, %5.</source>
        <translation>%1 muestras usadas, %2 filas descartadas (no finitas), %3 huecos. Suavidad de la trayectoria de la muñeca: %4, %5.</translation>
    </message>
    <message>
        <source>females aged %1-%2</source>
        <translation>mujeres de %1 a %2 años</translation>
    </message>
    <message>
        <source>males aged %1-%2</source>
        <translation>hombres de %1 a %2 años</translation>
    </message>
    <message>
        <source>%1 (maximum); %2 (minimum)</source>
        <translation>%1 (máximo); %2 (mínimo)</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: the date of birth is not recorded.</source>
        <translation>No se usan los valores de referencia por edad y sexo (Soucie et al. 2011): la fecha de nacimiento no está registrada.</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: the patient was %1 on the day of the session, outside the study&apos;s 2 to 69 years.</source>
        <translation>No se usan los valores de referencia por edad y sexo (Soucie et al. 2011): el paciente tenía %1 años el día de la sesión, fuera de los 2 a 69 años del estudio.</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: the patient&apos;s sex is not recorded as female or male.</source>
        <translation>No se usan los valores de referencia por edad y sexo (Soucie et al. 2011): el sexo del paciente no está registrado como femenino o masculino.</translation>
    </message>
    <message>
        <source>Reference values by age and sex (Soucie et al. 2011) are not used: this version has none for %1.</source>
        <translation>No se usan los valores de referencia por edad y sexo (Soucie et al. 2011): esta versión no tiene ninguno para %1.</translation>
    </message>
    <message>
        <source>Normal range (deg)</source>
        <translation>Rango normal (grados)</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Fuente</translation>
    </message>
    <message>
        <source>Soucie et al. give the mean passive range of motion of healthy %1; the patient was %2 on the day of the session.</source>
        <translation>Soucie et al. dan el rango de movimiento pasivo medio de personas sanas (%1); el paciente tenía %2 años el día de la sesión.</translation>
    </message>
    <message>
        <source>Shoulder extension</source>
        <translation>Extensión de hombro</translation>
    </message>
    <message>
        <source>Shoulder external rotation</source>
        <translation>Rotación externa de hombro</translation>
    </message>
    <message>
        <source>Forearm supination</source>
        <translation>Supinación del antebrazo</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <comment>the motion, beside the supination chart</comment>
        <translation>Pronación del antebrazo</translation>
    </message>
    <message>
        <source>no sessions</source>
        <translation>sin sesiones</translation>
    </message>
    <message>
        <source>until %1</source>
        <translation>hasta %1</translation>
    </message>
    <message>
        <source>from %1</source>
        <translation>desde %1</translation>
    </message>
    <message>
        <source>Period</source>
        <translation>Periodo</translation>
    </message>
    <message>
        <source>No sessions in the period (%1).</source>
        <translation>No hay sesiones en el periodo (%1).</translation>
    </message>
    <message>
        <source>; latest %1 % of normal</source>
        <translation>; última %1 % de lo normal</translation>
    </message>
    <message>
        <source>%1 of %2 deg, %3 %</source>
        <comment>the largest angle, its normal, the percent of normal</comment>
        <translation>%1 de %2°, %3 %</translation>
    </message>
    <message>
        <source>Grey: the normal range of motion; blue: this session&apos;s range (negative = extension, external rotation, supination). Shoulder adduction has no normal limit in the sources; its range is shown from 0. Beside each bar: the largest angle reached in the motion the angle is named after (flexion, abduction, internal rotation, elbow flexion, pronation), that motion&apos;s normal range, and the first as a percentage of the second, as on the patient&apos;s page. Sources: %1.</source>
        <translation>Gris: el rango de movimiento normal; azul: el rango de esta sesión (negativo = extensión, rotación externa, supinación). Las fuentes no dan un límite normal para la aducción del hombro; su rango se muestra desde 0. Junto a cada barra: el mayor ángulo alcanzado en el movimiento que da nombre al ángulo (flexión, abducción, rotación interna, flexión del codo, pronación), el rango normal de ese movimiento y el primero como porcentaje del segundo, como en la página del paciente. Fuentes: %1.</translation>
    </message>
    <message>
        <source>Events marked (time since the recording began, as in the review): %1</source>
        <translation>Eventos marcados (tiempo desde el inicio de la grabación, como en la revisión): %1</translation>
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
        <translation>Buena</translation>
    </message>
    <message>
        <source>Usable</source>
        <translation>Utilizable</translation>
    </message>
    <message>
        <source>Poor</source>
        <translation>Deficiente</translation>
    </message>
    <message>
        <source>Sensor calibration: %1.</source>
        <translation>Calibración de los sensores: %1.</translation>
    </message>
    <message>
        <source>Sensor calibration: %1</source>
        <translation>Calibración de los sensores: %1</translation>
    </message>
    <message>
        <source>Sensor calibration: %1. %2</source>
        <translation>Calibración de los sensores: %1. %2</translation>
    </message>
    <message>
        <source>Sensor calibration: none was made for this session; the lengths below are the ones the session was recorded with (measured or default).</source>
        <translation>Calibración de los sensores: no se hizo ninguna para esta sesión; las longitudes siguientes son con las que se grabó la sesión (medidas o predeterminadas).</translation>
    </message>
    <message>
        <source>Segments: upper arm %1 (shoulder to elbow), forearm %2 (elbow to wrist).</source>
        <translation>Segmentos: brazo %1 (del hombro al codo), antebrazo %2 (del codo a la muñeca).</translation>
    </message>
    <message>
        <source>%1 from the %2, mounted at %3 about the segment, %4 off its axis</source>
        <translation>a %1 del %2, montado a %3 alrededor del segmento, a %4 de su eje</translation>
    </message>
    <message>
        <source>shoulder</source>
        <translation>hombro</translation>
    </message>
    <message>
        <source>Upper-arm sensor: %1.</source>
        <translation>Sensor del brazo: %1.</translation>
    </message>
    <message>
        <source>elbow</source>
        <translation>codo</translation>
    </message>
    <message>
        <source>Forearm sensor: %1.</source>
        <translation>Sensor del antebrazo: %1.</translation>
    </message>
    <message>
        <source>Arm: %1.</source>
        <translation>Brazo: %1.</translation>
    </message>
    <message>
        <source>Camera: calibrated, %1 m from the shoulder.</source>
        <translation>Cámara: calibrada, a %1 m del hombro.</translation>
    </message>
    <message>
        <source>Camera: calibrated.</source>
        <translation>Cámara: calibrada.</translation>
    </message>
    <message>
        <source>Trunk compensation</source>
        <translation>Compensación del tronco</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>no medido</translation>
    </message>
    <message>
        <source>Not measured: the session had no sternum sensor (trunk IMU) and no optical shoulder position.</source>
        <translation>No medido: la sesión no tenía sensor en el esternón (IMU de tronco) ni posición óptica del hombro.</translation>
    </message>
    <message>
        <source>The largest trunk flexion (forward lean), lateral bending and axial rotation from the upright start pose, and the largest displacement of the shoulder, over the session and in each repetition.</source>
        <translation>La mayor flexión del tronco (inclinación hacia delante), inclinación lateral y rotación axial respecto a la postura inicial erguida, y el mayor desplazamiento del hombro, en la sesión y en cada repetición.</translation>
    </message>
    <message>
        <source>Trunk flexion</source>
        <translation>Flexión del tronco</translation>
    </message>
    <message>
        <source>Lateral bending</source>
        <translation>Inclinación lateral</translation>
    </message>
    <message>
        <source>Axial rotation</source>
        <translation>Rotación axial</translation>
    </message>
    <message>
        <source>Shoulder displacement</source>
        <translation>Desplazamiento del hombro</translation>
    </message>
    <message>
        <source>%1 of %2 repetitions were made with trunk compensation (trunk flexion over %3 deg).</source>
        <translation>%1 de %2 repeticiones se hicieron con compensación del tronco (flexión del tronco por encima de %3°).</translation>
    </message>
    <message>
        <source>Per repetition</source>
        <translation>Por repetición</translation>
    </message>
    <message>
        <source>Trunk flexion (deg)</source>
        <translation>Flexión del tronco (°)</translation>
    </message>
    <message>
        <source>Lateral bending (deg)</source>
        <translation>Inclinación lateral (°)</translation>
    </message>
    <message>
        <source>Axial rotation (deg)</source>
        <translation>Rotación axial (°)</translation>
    </message>
    <message>
        <source>Shoulder (cm)</source>
        <translation>Hombro (cm)</translation>
    </message>
    <message>
        <source>Compensated</source>
        <translation>Compensada</translation>
    </message>
    <message>
        <source>Trunk compensation: largest trunk flexion (deg)</source>
        <translation>Compensación del tronco: flexión máxima del tronco (°)</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleChart</name>
    <message>
        <source>Plot of %1 over time in degrees; the table beside it holds the same numbers</source>
        <translation>Gráfica de %1 en grados a lo largo del tiempo; la tabla de al lado contiene los mismos números</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Objetivo</translation>
    </message>
    <message>
        <source>Compared session</source>
        <translation>Sesión comparada</translation>
    </message>
    <message>
        <source>%1 (°)</source>
        <translation>%1 (°)</translation>
    </message>
    <message>
        <source>likely range</source>
        <translation>rango probable</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AnglePlotPanel</name>
    <message>
        <source>Joint angle plots</source>
        <translation>Gráficas de los ángulos articulares</translation>
    </message>
    <message>
        <source>Joint angles table</source>
        <translation>Tabla de los ángulos articulares</translation>
    </message>
    <message>
        <source>The current value of each angle, its uncertainty, the range over the plotted time and the target</source>
        <translation>El valor actual de cada ángulo, su incertidumbre, el rango en el tiempo mostrado y el objetivo</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleReadouts</name>
    <message>
        <source>Current joint angles</source>
        <translation>Ángulos articulares actuales</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>The angle lies within this range of the value shown, with about 95 % probability.</source>
        <translation>El ángulo está dentro de este margen del valor mostrado con una probabilidad de aproximadamente el 95 %.</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::AngleTableModel</name>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Now</source>
        <translation>Ahora</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Mín.</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Máx.</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Objetivo</translation>
    </message>
    <message>
        <source>Confidence</source>
        <translation>Confianza</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::Angles</name>
    <message>
        <source>Shoulder flexion</source>
        <translation>Flexión de hombro</translation>
    </message>
    <message>
        <source>Shoulder abduction</source>
        <translation>Abducción de hombro</translation>
    </message>
    <message>
        <source>Shoulder internal rotation</source>
        <translation>Rotación interna de hombro</translation>
    </message>
    <message>
        <source>Elbow flexion</source>
        <translation>Flexión de codo</translation>
    </message>
    <message>
        <source>Forearm pronation</source>
        <translation>Pronosupinación</translation>
    </message>
    <message>
        <source>sensor lost</source>
        <translation>sensor perdido</translation>
    </message>
    <message>
        <source>heading</source>
        <translation>rumbo</translation>
    </message>
    <message>
        <source>heading from the start pose</source>
        <translation>rumbo solo de la postura inicial</translation>
    </message>
    <message>
        <source>uncertain</source>
        <translation>incierto</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::ArmView</name>
    <message>
        <source>3D view of the arm</source>
        <translation>Vista 3D del brazo</translation>
    </message>
    <message>
        <source>The estimated arm with its sensors. Arrow keys turn the view, plus and minus zoom, Home resets the view.</source>
        <translation>El brazo calculado con sus sensores. Las flechas giran la vista, más y menos hacen zoom, Inicio restablece la vista.</translation>
    </message>
    <message>
        <source>Drag to turn the view, scroll to zoom; Home resets it</source>
        <translation>Arrastre para girar la vista, use la rueda para el zoom; Inicio la restablece</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Restablecer la vista</translation>
    </message>
    <message>
        <source>Left arm</source>
        <translation>Brazo izquierdo</translation>
    </message>
    <message>
        <source>Right arm</source>
        <translation>Brazo derecho</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceHealthModel</name>
    <message>
        <source>Device</source>
        <translation>Dispositivo</translation>
    </message>
    <message>
        <source>Stream</source>
        <translation>Flujo</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>Frecuencia</translation>
    </message>
    <message>
        <source>Lost</source>
        <translation>Perdidas</translation>
    </message>
    <message>
        <source>Rejected</source>
        <translation>Rechazadas</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>aviso</translation>
    </message>
    <message>
        <source>down</source>
        <translation>caído</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>inactivo</translation>
    </message>
    <message>
        <source>%L1 Hz</source>
        <translation>%L1 Hz</translation>
    </message>
    <message>
        <source>Battery low: charge the device after the session</source>
        <translation>Batería baja: cargue el dispositivo después de la sesión</translation>
    </message>
    <message>
        <source>The device does not report its battery</source>
        <translation>El dispositivo no informa de su batería</translation>
    </message>
    <message>
        <source>not reported</source>
        <translation>no informado</translation>
    </message>
    <message>
        <source>%L1 %, low</source>
        <translation>%L1 %, baja</translation>
    </message>
    <message>
        <source>%L1 %</source>
        <translation>%L1 %</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Batería</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceHealthPanel</name>
    <message>
        <source>Device health</source>
        <translation>Estado de los dispositivos</translation>
    </message>
    <message>
        <source>Device health summary</source>
        <translation>Resumen del estado de los dispositivos</translation>
    </message>
    <message>
        <source>Devices and streams</source>
        <translation>Dispositivos y flujos</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceOptionsForm</name>
    <message>
        <source>Device options</source>
        <translation>Opciones del dispositivo</translation>
    </message>
    <message>
        <source>(not set)</source>
        <translation>(sin definir)</translation>
    </message>
    <message>
        <source>Ports found...</source>
        <translation>Puertos encontrados...</translation>
    </message>
    <message>
        <source>Serial ports found on this computer</source>
        <translation>Puertos serie encontrados en este ordenador</translation>
    </message>
    <message>
        <source>No serial port found: plug the sensor&apos;s receiver in (or pair the Bluetooth sensor), then look again</source>
        <translation>No se encontró ningún puerto serie: conecte el receptor del sensor (o empareje el sensor Bluetooth) y vuelva a mirar</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::DeviceWords</name>
    <message>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>conectando</translation>
    </message>
    <message>
        <source>streaming</source>
        <translation>transmitiendo</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>simulated IMUs, Kinect and webcam in real time, with fault injection</source>
        <translation>IMU, Kinect y webcam simulados en tiempo real, con fallos inyectados</translation>
    </message>
    <message>
        <source>Kinect v1 (libfreenect): elbow and wrist markers in 3D, shoulder frame</source>
        <translation>Kinect v1 (libfreenect): marcadores de codo y muñeca en 3D, en el sistema del hombro</translation>
    </message>
    <message>
        <source>do-it-yourself IMU (ESP32/Arduino) sending ArmTrack&apos;s $IMU text lines over a serial port or UDP</source>
        <translation>IMU casera (ESP32/Arduino) que envía las líneas de texto $IMU de ArmTrack por un puerto serie o UDP</translation>
    </message>
    <message>
        <source>x-io NGIMU over Wi-Fi (OSC over UDP, /sensors messages)</source>
        <translation>x-io NGIMU por wifi (OSC sobre UDP, mensajes /sensors)</translation>
    </message>
    <message>
        <source>Shimmer3 IMU (LogAndStream firmware) over its Bluetooth serial port</source>
        <translation>IMU Shimmer3 (firmware LogAndStream) por su puerto serie Bluetooth</translation>
    </message>
    <message>
        <source>elbow and wrist positions from an external body tracker (Kinect SDK, pose estimator), JSON over UDP</source>
        <translation>posiciones de codo y muñeca de un seguidor corporal externo (Kinect SDK, estimador de pose), JSON sobre UDP</translation>
    </message>
    <message>
        <source>wrist and elbow marker pixels from a camera or a video file (OpenCV)</source>
        <translation>píxeles de los marcadores de muñeca y codo de una cámara o un archivo de vídeo (OpenCV)</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::HealthTracker</name>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>error: %1</source>
        <translation>error: %1</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>reconectando</translation>
    </message>
    <message>
        <source>reconnecting: %1</source>
        <translation>reconectando: %1</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>conectando</translation>
    </message>
    <message>
        <source>no data for %L1 s</source>
        <translation>sin datos desde hace %L1 s</translation>
    </message>
    <message>
        <source>waiting for data</source>
        <translation>esperando datos</translation>
    </message>
    <message>
        <source>streaming, losing samples</source>
        <translation>transmitiendo, con pérdida de muestras</translation>
    </message>
    <message>
        <source>streaming</source>
        <translation>transmitiendo</translation>
    </message>
    <message>
        <source>No devices</source>
        <translation>No hay dispositivos</translation>
    </message>
    <message>
        <source>All devices are streaming</source>
        <translation>Todos los dispositivos transmiten</translation>
    </message>
    <message>
        <source>Trunk (sternum) sensor</source>
        <translation>Sensor del tronco (esternón)</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::RepetitionCounterWidget</name>
    <message>
        <source>Repetitions</source>
        <translation>Repeticiones</translation>
    </message>
    <message>
        <source>Repetitions done of the target</source>
        <translation>Repeticiones hechas del objetivo</translation>
    </message>
    <message>
        <source>Repetitions (%1)</source>
        <translation>Repeticiones (%1)</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 de %2</translation>
    </message>
    <message numerus="yes">
        <source>%n partial</source>
        <translation>
            <numerusform>%n parcial</numerusform>
            <numerusform>%n parciales</numerusform>
        </translation>
    </message>
    <message>
        <source>moving</source>
        <translation>en movimiento</translation>
    </message>
    <message>
        <source>target reached</source>
        <translation>objetivo alcanzado</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::TrunkChart</name>
    <message>
        <source>Trunk flexion</source>
        <translation>Flexión del tronco</translation>
    </message>
    <message>
        <source>Trunk lateral bending</source>
        <translation>Inclinación lateral del tronco</translation>
    </message>
    <message>
        <source>Trunk axial rotation</source>
        <translation>Rotación axial del tronco</translation>
    </message>
    <message>
        <source>Trunk</source>
        <translation>Tronco</translation>
    </message>
    <message>
        <source>%1 (°)</source>
        <translation>%1 (°)</translation>
    </message>
    <message>
        <source>Trunk plot</source>
        <translation>Gráfico del tronco</translation>
    </message>
    <message>
        <source>Trunk flexion, lateral bending and axial rotation over time in degrees, relative to the start pose</source>
        <translation>Flexión, inclinación lateral y rotación axial del tronco a lo largo del tiempo en grados, respecto a la postura inicial</translation>
    </message>
</context>
<context>
    <name>armtrack::ui::VtkBridge</name>
    <message>
        <source>OpenGL is not available, so the 3D view cannot be shown.</source>
        <translation>OpenGL no está disponible, así que no se puede mostrar la vista 3D.</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.2; this display offers %1.%2.</source>
        <translation>La vista 3D necesita OpenGL 3.2; esta pantalla ofrece %1.%2.</translation>
    </message>
</context>
</TS>
