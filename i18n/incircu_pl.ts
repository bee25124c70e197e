<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL">
<context>
    <name>IncirCuAlgorithm</name>
    <message>
        <location filename="../algorithms/base.py" line="158"/>
        <source>Centerlines</source>
        <translation>Linie środkowe</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="362"/>
        <source>Store the local width as M value</source>
        <translation>Zapisz lokalną szerokość jako wartość M</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="384"/>
        <source>Centerline vertices</source>
        <translation>Wierzchołki linii środkowej</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="384"/>
        <source>Incircles</source>
        <translation>Okręgi wpisane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="384"/>
        <source>Transects</source>
        <translation>Przekroje poprzeczne</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="412"/>
        <source>Distance between transects (0 = mean width)</source>
        <translation>Odległość między przekrojami (0 = średnia szerokość)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="422"/>
        <source>Number of centerlines</source>
        <translation>Liczba linii środkowych</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="422"/>
        <source>Number of centerline features written.</source>
        <translation>Liczba zapisanych obiektów linii środkowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="427"/>
        <source>Number of skipped features</source>
        <translation>Liczba pominiętych obiektów</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="427"/>
        <source>Number of input features (or parts) skipped with a warning.</source>
        <translation>Liczba obiektów wejściowych (lub ich części) pominiętych z ostrzeżeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/dependencies.py" line="49"/>
        <source>IncirCu needs the Python package Shapely 2, which is not installed.</source>
        <translation>IncirCu wymaga pakietu Pythona Shapely 2, który nie jest zainstalowany.</translation>
    </message>
    <message>
        <location filename="../algorithms/dependencies.py" line="58"/>
        <source>IncirCu needs Shapely 2.0 or newer, but Shapely {} is installed.</source>
        <translation>IncirCu wymaga Shapely 2.0 lub nowszego, a zainstalowany jest Shapely {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="99"/>
        <source>{} must be a {} layer, but &apos;{}&apos; holds {} geometries.</source>
        <translation>{} musi być warstwą typu {}, a '{}' zawiera geometrie typu {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="55"/>
        <source>the feature has no geometry</source>
        <translation>obiekt nie ma geometrii</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="191"/>
        <source>Feature {} skipped: {}</source>
        <translation>Obiekt {} pominięty: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="199"/>
        <source>Feature {}: {}</source>
        <translation>Obiekt {}: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="218"/>
        <source>{} (part {})</source>
        <translation>{} (część {})</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="242"/>
        <source>unexpected {}: {} (please report this with the feature)</source>
        <translation>nieoczekiwany błąd {}: {} (prosimy zgłosić go wraz z obiektem)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="362"/>
        <source>Write the incircle diameter (local width, layer units or metres) as M value of each vertex.</source>
        <translation>Zapisz średnicę okręgu wpisanego (lokalną szerokość, w jednostkach warstwy lub metrach) jako wartość M każdego wierzchołka.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="384"/>
        <source>Optional point layer: every centerline vertex with its chainage, incircle radius and width.</source>
        <translation>Opcjonalna warstwa punktowa: każdy wierzchołek linii środkowej z kilometrażem, promieniem okręgu wpisanego i szerokością.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="384"/>
        <source>Optional polygon layer: the incircle of every vertex, with its radius and chainage.</source>
        <translation>Opcjonalna warstwa poligonowa: okrąg wpisany każdego wierzchołka z promieniem i kilometrażem.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="412"/>
        <source>Distance along the centerline between two transects, layer units (metres for a layer in degrees); 0 uses the mean width of each centerline.</source>
        <translation>Odległość wzdłuż linii środkowej między dwoma przekrojami, w jednostkach warstwy (w metrach dla warstwy w stopniach); 0 oznacza średnią szerokość każdej linii środkowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/outputs.py" line="202"/>
        <source>Could not write a centerline: {}</source>
        <translation>Nie udało się zapisać linii środkowej: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="384"/>
        <source>Optional line layer: cross-sections from bank to bank through the centerline, one every &apos;Distance between transects&apos;, with their width and chainage.</source>
        <translation>Opcjonalna warstwa liniowa: przekroje poprzeczne od brzegu do brzegu przez linię środkową, jeden co 'Odległość między przekrojami', z szerokością i kilometrażem.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="267"/>
        <source>Largest deviation from the exact medial axis (0 = automatic)</source>
        <translation>Największe odchylenie od dokładnej osi środkowej (0 = automatycznie)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="278"/>
        <source>Fixed boundary sampling distance (0 = adaptive)</source>
        <translation>Stały odstęp próbkowania brzegu (0 = adaptacyjnie)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="278"/>
        <source>The paper&apos;s fixed sampling: a sample every this distance along both sides, in layer units (metres for a layer in degrees), giving many evenly spaced vertices. Use it to reproduce the paper or for a dense line; 0 uses the adaptive sampling bounded by the largest deviation. Give either this or the largest deviation, not both.</source>
        <translation>Stałe próbkowanie z artykułu: próbka co tę odległość wzdłuż obu stron, w jednostkach warstwy (metry dla warstwy w stopniach), dające wiele równomiernie rozmieszczonych wierzchołków. Do odtworzenia artykułu lub gęstej linii; 0 oznacza próbkowanie adaptacyjne ograniczone największym odchyleniem. Podaj to albo największe odchylenie, nie oba.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="302"/>
        <source>Give either a largest deviation from the axis (adaptive sampling) or a fixed boundary sampling distance, not both; set the other one to 0.</source>
        <translation>Podaj największe odchylenie od osi (próbkowanie adaptacyjne) albo stały odstęp próbkowania brzegu, nie oba; ustaw drugie na 0.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="312"/>
        <source>Split point snapping tolerance</source>
        <translation>Tolerancja przyciągania punktów podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="312"/>
        <source>Largest distance between a split point and the polygon&apos;s exterior ring, layer units (metres for a layer in degrees); 0 = a millionth of the polygon&apos;s size.</source>
        <translation>Największa odległość punktu podziału od zewnętrznego obrysu poligonu, w jednostkach warstwy (w metrach dla warstwy w stopniach); 0 = jedna milionowa rozmiaru poligonu.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="341"/>
        <source>Islands (holes)</source>
        <translation>Wyspy (otwory)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="337"/>
        <source>Pass through the main channel</source>
        <translation>Prowadź głównym korytem</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="337"/>
        <source>Ignore islands</source>
        <translation>Pomijaj wyspy</translation>
    </message>
    <message>
        <location filename="../algorithms/network_outputs.py" line="171"/>
        <source>Could not write a branch: {}</source>
        <translation>Nie można zapisać gałęzi: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/units.py" line="21"/>
        <source>layer units</source>
        <translation>jednostki warstwy</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="134"/>
        <source>{}: {} has no field &apos;{}&apos;; its fields are: {}.</source>
        <translation>{}: {} nie ma pola '{}'; jego pola to: {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="134"/>
        <source>none</source>
        <translation>brak</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="196"/>
        <source>Parameters</source>
        <translation>Parametry</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="196"/>
        <source>Advanced parameters</source>
        <translation>Parametry zaawansowane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="196"/>
        <source>Outputs</source>
        <translation>Wyniki</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="267"/>
        <source>Largest distance between the centerline and the exact medial axis, in layer units (metres for a layer in degrees): the line keeps only the vertices it needs to stay that close, each lying exactly on the axis, and never leaves the shape whatever the value. 0 uses 1/200 of the shape&apos;s typical width: the right choice for maps.</source>
        <translation>Największa odległość linii środkowej od dokładnej osi środkowej, w jednostkach warstwy (metry dla warstwy w stopniach): linia zachowuje tylko wierzchołki potrzebne, by pozostać tak blisko, każdy leżący dokładnie na osi, i nigdy nie wychodzi poza kształt, niezależnie od wartości. 0 oznacza 1/200 typowej szerokości kształtu: właściwy wybór dla map.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="118"/>
        <source>Z values are ignored: &apos;{}&apos; has Z, but the centerline is computed in the plane and written without Z (its M values, when stored, are the local width).</source>
        <translation>Wartości Z są pomijane: '{}' ma współrzędną Z, ale linia środkowa jest obliczana na płaszczyźnie i zapisywana bez Z (jej wartości M, jeśli są zapisywane, to lokalna szerokość).</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="348"/>
        <source>Connect features that share a boundary</source>
        <translation>Połącz obiekty o wspólnej granicy</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="348"/>
        <source>Where two polygons of the layer share a stretch of boundary (a river cut into reaches, water or road-area pieces), the middle of that stretch becomes an end of both, so their lines meet there exactly (and, in a network, share the node id). A polygon with one such gate gets its other end(s) automatically.</source>
        <translation>Gdzie dwa poligony warstwy mają wspólny odcinek granicy (rzeka pocięta na odcinki, kawałki wód lub powierzchni dróg), środek tego odcinka staje się końcem obu, więc ich linie spotykają się tam dokładnie (a w sieci mają wspólny identyfikator węzła). Poligon z jedną taką bramą dostaje pozostałe końce automatycznie.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="340"/>
        <source>Channels on both sides of large islands</source>
        <translation>Koryta po obu stronach dużych wysp</translation>
    </message>
</context>
<context>
    <name>LinesCenterlineAlgorithm</name>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="51"/>
        <source>centerline,centreline,medial axis,banks,river,road,width,incircle</source>
        <translation>linia środkowa,oś,oś medialna,brzegi,rzeka,droga,szerokość,okrąg wpisany</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="65"/>
        <source>First lines (bank A)</source>
        <translation>Pierwsze linie (brzeg A)</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="72"/>
        <source>Second lines (bank B)</source>
        <translation>Drugie linie (brzeg B)</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="76"/>
        <source>Pairing field of the first lines</source>
        <translation>Pole parujące pierwszych linii</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="88"/>
        <source>Pairing field of the second lines</source>
        <translation>Pole parujące drugich linii</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="124"/>
        <source>{} holds no line.</source>
        <translation>{} nie zawiera żadnej linii.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="33"/>
        <source>Centerline between two lines</source>
        <translation>Linia środkowa między dwiema liniami</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="36"/>
        <source>One unbranched centerline between two lines, such as the two banks of a river.</source>
        <translation>Jedna nierozgałęziona linia środkowa między dwiema liniami, na przykład brzegami rzeki.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="39"/>
        <source>Centerline between lines</source>
        <translation>Linia środkowa między liniami</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="54"/>
        <source>Computes one unbranched centerline between two lines (for example the two banks of a river) with the Curve of Incircles: every vertex is the centre of a circle touching both lines. Lines are paired by equal values of the two pairing fields; without them each layer holds one line (its features and parts are merged). The lines must not cross. The M value of each vertex is the local width. The second lines are reprojected to the CRS of the first; geographic layers are computed in a local metric projection and distances are then in metres.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową między dwiema liniami (na przykład brzegami rzeki) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu linii. Linie łączone są w pary według równych wartości obu pól parujących; bez nich każda warstwa zawiera jedną linię (jej obiekty i części są scalane). Linie nie mogą się przecinać. Wartość M każdego wierzchołka to lokalna szerokość. Drugie linie są przeliczane do układu pierwszych; warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym, a odległości są wtedy w metrach.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="72"/>
        <source>Line layer of the other side; reprojected to the CRS of the first lines when needed.</source>
        <translation>Warstwa liniowa drugiej strony; w razie potrzeby przeliczana do układu pierwszych linii.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="76"/>
        <source>Optional; a line of the first lines is paired with the line of the second lines that has the same value in &apos;Pairing field of the second lines&apos;.</source>
        <translation>Opcjonalne; linia z pierwszych linii łączona jest w parę z linią z drugich linii o tej samej wartości w 'Pole parujące drugich linii'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="88"/>
        <source>Optional; required together with &apos;Pairing field of the first lines&apos;.</source>
        <translation>Opcjonalne; wymagane razem z 'Pole parujące pierwszych linii'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="42"/>
        <source>Line layer, one line per pair of lines: the attributes of the first lines plus source_fid (the id of the pair&apos;s first feature in the first lines), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices. Its ends_found (always false) and ends_from (always empty) are there only so that it has the fields of &apos;Centerline of polygons&apos;.</source>
        <translation>Warstwa liniowa, jedna linia na parę linii: atrybuty pierwszych linii oraz source_fid (identyfikator pierwszego obiektu pary w pierwszych liniach), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach) i n_vertices. Pola ends_found (zawsze fałsz) i ends_from (zawsze puste) istnieją tylko po to, by warstwa miała pola algorytmu 'Linia środkowa poligonów'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="65"/>
        <source>Line layer of one side; the output has its CRS and its attributes. Z values (of both layers) are ignored: the centerline is computed in the plane.</source>
        <translation>Warstwa liniowa jednej strony; wynik ma jej układ współrzędnych i atrybuty. Wartości Z (obu warstw) są pomijane: linia środkowa jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="109"/>
        <source>Give both {} and {}, or neither (then each layer holds one line).</source>
        <translation>Podaj oba pola, {} i {}, albo żadnego (wtedy każda warstwa zawiera jedną linię).</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="127"/>
        <source>{} holds {} separate lines that do not join into one; give {} and {} to pair them, or merge them into one line.</source>
        <translation>{} zawiera linie, które nie łączą się w jedną (jest ich {}); podaj {} i {}, aby je sparować, albo scal je w jedną linię.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="146"/>
        <source>No line in {} has {} = {!r}; line {} of {} unused.</source>
        <translation>Żadna linia w {} nie ma {} = {!r}; linia {} z {} nie została użyta.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="156"/>
        <source>no line in {} has {} = {!r}</source>
        <translation>żadna linia w {} nie ma {} = {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="174"/>
        <source>the lines of {} with this pairing value do not join into one</source>
        <translation>linie z {} o tej wartości parowania nie łączą się w jedną</translation>
    </message>
</context>
<context>
    <name>PolygonCenterlineAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="57"/>
        <source>centerline,centreline,medial axis,skeleton,river,road,dike,width,incircle</source>
        <translation>linia środkowa,oś,oś medialna,szkielet,rzeka,droga,wał,szerokość,okrąg wpisany</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="72"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="81"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="128"/>
        <source>One feature per polygon part</source>
        <translation>Jeden obiekt na każdą część poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="128"/>
        <source>Write one line feature per part of a multipart polygon instead of one MultiLineString per input feature.</source>
        <translation>Zapisz osobny obiekt liniowy dla każdej części poligonu wieloczęściowego zamiast jednego MultiLineString na obiekt wejściowy.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="40"/>
        <source>Centerline of polygons</source>
        <translation>Linia środkowa poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="43"/>
        <source>One unbranched centerline through each elongated polygon (river, road, dike).</source>
        <translation>Jedna nierozgałęziona linia środkowa każdego wydłużonego poligonu (rzeki, drogi, wału).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="46"/>
        <source>Centerlines of polygons</source>
        <translation>Linie środkowe poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="60"/>
        <source>Computes one unbranched, loop-free centerline for each polygon (each part of a multipart polygon) with the Curve of Incircles: every vertex is the centre of a circle touching both sides of the outline. The line runs between the two &apos;Split points&apos; lying on the polygon&apos;s outline, or, without them, between automatic ends: those of the internal path along the &apos;Guide lines&apos;, else of the main stem (or the longest internal path, see &apos;Automatic ends&apos;). Islands (holes) are passed on the side of the wider channel, or ignored. The M value of each vertex is the local width. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową bez pętli dla każdego poligonu (każdej części poligonu wieloczęściowego) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu stron obrysu. Linia biegnie między dwoma 'Punktami podziału' leżącymi na obrysie poligonu, a bez nich między końcami automatycznymi: końcami drogi wewnątrz kształtu wzdłuż 'Linii prowadzących', a bez nich głównego nurtu (lub najdłuższej drogi wewnątrz kształtu, zob. 'Końce automatyczne'). Wyspy (otwory) są omijane od strony szerszego koryta albo pomijane. Wartość M każdego wierzchołka to lokalna szerokość. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie da się przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="105"/>
        <source>Automatic ends</source>
        <translation>Końce automatyczne</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="104"/>
        <source>Main stem (widest path)</source>
        <translation>Główny nurt (najszersza droga)</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="104"/>
        <source>Longest path</source>
        <translation>Najdłuższa droga</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="115"/>
        <source>Guide lines</source>
        <translation>Linie prowadzące</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="115"/>
        <source>Rough river lines (a national network, OpenStreetMap waterways) for polygons without split points: the ends are those of the internal path that best covers the guide lines near the polygon. Gaps, offsets, generalised pieces and tributaries are fine. Another CRS is reprojected.</source>
        <translation>Przybliżone linie rzek (sieć krajowa, cieki OpenStreetMap) dla poligonów bez punktów podziału: końcami są końce drogi wewnątrz kształtu, która najlepiej pokrywa linie prowadzące w pobliżu poligonu. Przerwy, przesunięcia, uogólnione fragmenty i dopływy nie przeszkadzają. Inny układ współrzędnych jest przeliczany.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="72"/>
        <source>Elongated polygons (rivers, roads, dikes); multipart polygons get one centerline per part. Z values are ignored: the centerline is computed in the plane.</source>
        <translation>Wydłużone poligony (rzeki, drogi, wały); poligony wieloczęściowe dostają jedną linię środkową na część. Wartości Z są pomijane: linia środkowa jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="97"/>
        <source>{pass_through}: the line never crosses an island and goes round it on the side of the wider channel. {ignore}: holes are filled before computing.</source>
        <translation>{pass_through}: linia nigdy nie przecina wyspy i omija ją od strony szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="105"/>
        <source>For polygons without split points. {main_stem}: the internal path that sweeps the largest channel area (length times width), so a wide main river wins over a longer but narrow side arm. {longest_path}: the tips of the two longest arms.</source>
        <translation>Dla poligonów bez punktów podziału. {main_stem}: droga wewnątrz kształtu obejmująca największą powierzchnię koryta (długość razy szerokość), więc szeroka rzeka główna wygrywa z dłuższą, lecz wąską odnogą. {longest_path}: końce dwóch najdłuższych ramion.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="249"/>
        <source>0: a millionth of the polygon&apos;s size</source>
        <translation>0: jedna milionowa rozmiaru poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="228"/>
        <source>{} Its ends were found automatically.</source>
        <translation>{} Jego końce wyznaczono automatycznie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="251"/>
        <source>{} holds no point.</source>
        <translation>{} nie zawiera żadnego punktu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="252"/>
        <source>no split point lies within {} of its outline, the {}; the nearest is {:.6g} {} away.</source>
        <translation>żaden punkt podziału nie leży w odległości {} od jego obrysu, czyli w granicach {}; najbliższy jest w odległości {:.6g} {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="49"/>
        <source>Line layer: input attributes plus source_fid (the polygon&apos;s feature id, to join the line back to it), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees), n_vertices, ends_found (true when no split points were used) and ends_from (split_points, guide, automatic, or split_points_and_automatic for one given split point).</source>
        <translation>Warstwa liniowa: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia linii z nim), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach), n_vertices, ends_found (prawda, gdy nie użyto punktów podziału) i ends_from (split_points, guide, automatic lub split_points_and_automatic dla jednego podanego punktu podziału).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="81"/>
        <source>Points marking where each centerline starts and ends: two per polygon part, within &apos;Split point snapping tolerance&apos; of its exterior ring. A part with none gets automatic ends; a part with one starts there and ends at the far end of its main stem; a part with more than two is skipped. Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Punkty wyznaczające początek i koniec każdej linii środkowej: dwa na część poligonu, w odległości nie większej niż 'Tolerancja przyciągania punktów podziału' od jej pierścienia zewnętrznego. Część bez punktów dostaje końce automatyczne; część z jednym zaczyna się w nim i kończy na dalszym końcu swojego głównego nurtu; część z więcej niż dwoma jest pomijana. Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
</context>
<context>
    <name>PolygonNetworkAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_network.py" line="37"/>
        <source>Centerline network of polygons</source>
        <translation>Sieć linii środkowych poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="40"/>
        <source>The medial-axis tree between the arm ends of a confluence, a delta or a road junction.</source>
        <translation>Drzewo osi środkowej między końcami ramion zlewiska, delty lub skrzyżowania dróg.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="44"/>
        <source>Network branches</source>
        <translation>Gałęzie sieci</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="47"/>
        <source>network,confluence,delta,junction,crossing,medial axis,skeleton,river,road,width</source>
        <translation>sieć,zlewisko,delta,węzeł,skrzyżowanie,oś środkowa,szkielet,rzeka,droga,szerokość</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="69"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="78"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="89"/>
        <source>Split point id field</source>
        <translation>Pole identyfikatora punktu podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="89"/>
        <source>Attribute naming each split point in from_point, to_point and the chains; default: its feature id.</source>
        <translation>Atrybut nazywający każdy punkt podziału w from_point, to_point i łańcuchach; domyślnie: identyfikator obiektu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="167"/>
        <source>Number of branches</source>
        <translation>Liczba gałęzi</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="167"/>
        <source>Number of branch features written.</source>
        <translation>Liczba zapisanych obiektów gałęzi.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="69"/>
        <source>Polygons with several arms (confluences, deltas, road junctions); each part gets its network. Z values are ignored: the network is computed in the plane.</source>
        <translation>Poligony z kilkoma ramionami (zlewiska, delty, skrzyżowania dróg); każda część dostaje swoją sieć. Wartości Z są pomijane: sieć jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="50"/>
        <source>Computes, for each polygon (each part of a multipart polygon), the part of the medial axis that separates the outline&apos;s chains between its ends (the ends of the arms of a confluence, a lake, a delta or a road junction): a tree with one end at each arm and junctions where a circle touches three chains, without side branches. The ends are the &apos;Split points&apos; on the outline when a part has two or more; otherwise they are found automatically (one given split point replaces the automatic end nearest to it): an arm counts when it reaches beyond the circle of the junction it leaves by at least &apos;Minimum arm length, in junction widths&apos; (bank noise and small bays do not). Each branch is one line feature with its node ids (from_node, to_node, shared by the branches that meet), its kind, the ids of the split points at its ends (&apos;gate&apos; at a gate, &apos;auto&apos; at an automatic end, &apos;junction&apos; at a junction), the chains on its right and left, its length and widths; the M value of each vertex is the local width. Two split points give exactly the polygon centerline. Islands (holes) are passed on the side of the wider channel, or ignored. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Wyznacza dla każdego poligonu (każdej części poligonu wieloczęściowego) tę część osi środkowej, która rozdziela łańcuchy obrysu między jego końcami (końcami ramion zlewiska, jeziora, delty lub skrzyżowania dróg): drzewo z jednym końcem w każdym ramieniu i węzłami tam, gdzie okrąg styka się z trzema łańcuchami, bez bocznych odgałęzień. Końcami są 'Punkty podziału' na obrysie, gdy część ma ich dwa lub więcej; w przeciwnym razie są wyznaczane automatycznie (jeden podany punkt podziału zastępuje najbliższy mu koniec automatyczny): ramię się liczy, gdy sięga poza okrąg węzła, od którego odchodzi, o co najmniej 'Minimalna długość ramienia, w szerokościach węzła' (szum brzegu i małe zatoki nie sięgają). Każda gałąź to jeden obiekt liniowy z identyfikatorami węzłów (from_node, to_node, wspólnymi dla gałęzi, które się spotykają), rodzajem, identyfikatorami punktów podziału na końcach ('gate' przy bramie, 'auto' przy końcu automatycznym, 'junction' w węźle), łańcuchami po prawej i lewej, długością i szerokościami; wartość M każdego wierzchołka to lokalna szerokość. Dwa punkty podziału dają dokładnie linię środkową poligonu. Wyspy (otwory) są omijane po stronie szerszego koryta albo pomijane. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie da się przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="78"/>
        <source>The ends of the network, within &apos;Split point snapping tolerance&apos; of a part&apos;s exterior ring, typically one across each arm&apos;s end. A part with two or more uses exactly these; a part with none or one gets its arm ends automatically (the one given replaces the automatic end nearest to it, when within that arm&apos;s width). Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Końce sieci, w odległości nie większej niż 'Tolerancja przyciągania punktów podziału' od pierścienia zewnętrznego części, zwykle po jednym w poprzek końca każdego ramienia. Część z dwoma lub więcej używa dokładnie ich; część bez punktu lub z jednym dostaje końce ramion automatycznie (podany punkt zastępuje najbliższy mu koniec automatyczny, jeśli leży w obrębie szerokości tego ramienia). Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="114"/>
        <source>Minimum arm length, in junction widths</source>
        <translation>Minimalna długość ramienia, w szerokościach węzła</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="114"/>
        <source>Automatic ends: an arm is kept when it reaches beyond the circle of the junction it leaves by at least this many widths of that junction (1: bank bumps, digitising steps and bays shallower than the river is wide make no branch; a tributary does).</source>
        <translation>Końce automatyczne: ramię zostaje, gdy sięga poza okrąg węzła, od którego odchodzi, o co najmniej tyle szerokości tego węzła (1: garby brzegu, schodki digitalizacji i zatoki płytsze niż szerokość rzeki nie tworzą gałęzi; dopływ tworzy).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="128"/>
        <source>Minimum arm length</source>
        <translation>Minimalna długość ramienia</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="128"/>
        <source>Automatic ends: an arm is kept only when it also reaches at least this far beyond its junction&apos;s circle, layer units (metres for a layer in degrees); 0 = no such limit. For generalisation.</source>
        <translation>Końce automatyczne: ramię zostaje tylko wtedy, gdy sięga też co najmniej tak daleko poza okrąg swojego węzła, w jednostkach warstwy (metry dla warstwy w stopniach); 0 = bez takiego ograniczenia. Do generalizacji.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="140"/>
        <source>Line layer, one feature per branch: input attributes plus source_fid (the polygon&apos;s feature id, to join the branch back to it), from_point, to_point (split point ids, &apos;gate&apos;, &apos;auto&apos; or &apos;junction&apos;), from_node, to_node (node ids shared by the branches that meet, also across polygons whose ends coincide), kind (arm, inner or loop), right_chain, left_chain (each chain named &apos;a-b&apos; after the ends at its ends, counter-clockwise), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices.</source>
        <translation>Warstwa liniowa, jeden obiekt na gałąź: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia gałęzi z nim), from_point, to_point (identyfikatory punktów podziału, 'gate', 'auto' lub 'junction'), from_node, to_node (identyfikatory węzłów wspólne dla spotykających się gałęzi, także między poligonami o wspólnych końcach), kind (arm, inner lub loop), right_chain, left_chain (każdy łańcuch nazwany 'a-b' od końców na jego krańcach, przeciwnie do ruchu wskazówek zegara), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach) i n_vertices.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="154"/>
        <source>Network nodes</source>
        <translation>Węzły sieci</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="154"/>
        <source>Optional point layer: every end and junction with its node id, degree (number of branch ends), radius (the junction&apos;s circle; 0 at an end) and kind (end or junction).</source>
        <translation>Opcjonalna warstwa punktowa: każdy koniec i węzeł z identyfikatorem węzła, stopniem (liczbą końców gałęzi), promieniem (okręgu węzła; 0 na końcu) i rodzajem (end lub junction).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="102"/>
        <source>{pass_through}: no branch crosses an island; each island belongs to the chain it is nearer to, so the branches go round it on the side of the wider channel. {ignore}: holes are filled before computing. {channels}: every island at least as long as the river around it is wide (its own width plus twice its distance to the nearest bank or island) gets a branch on each side, so the network has a loop around it with exact junctions up- and downstream (branches of kind &apos;loop&apos;); smaller islands are passed on the side of the wider channel.</source>
        <translation>{pass_through}: żadna gałąź nie przecina wyspy; każda wyspa należy do łańcucha, do którego jest bliżej, więc gałęzie omijają ją po stronie szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem. {channels}: każda wyspa co najmniej tak długa, jak szeroka jest rzeka wokół niej (jej własna szerokość plus dwukrotna odległość do najbliższego brzegu lub wyspy), dostaje gałąź z każdej strony, więc sieć ma wokół niej pętlę z dokładnymi węzłami powyżej i poniżej (gałęzie rodzaju 'loop'); mniejsze wyspy są omijane po stronie szerszego koryta.</translation>
    </message>
</context>
</TS>
