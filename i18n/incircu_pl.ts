<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL">
<context>
    <name>IncirCuAlgorithm</name>
    <message>
        <location filename="../algorithms/base.py" line="163"/>
        <source>Centerlines</source>
        <translation>Linie środkowe</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="426"/>
        <source>Store the local width as M value</source>
        <translation>Zapisz lokalną szerokość jako wartość M</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="448"/>
        <source>Centerline vertices</source>
        <translation>Wierzchołki linii środkowej</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="448"/>
        <source>Incircles</source>
        <translation>Okręgi wpisane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="448"/>
        <source>Transects</source>
        <translation>Przekroje poprzeczne</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="476"/>
        <source>Distance between transects (0 = mean width)</source>
        <translation>Odległość między przekrojami (0 = średnia szerokość)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="486"/>
        <source>Number of centerlines</source>
        <translation>Liczba linii środkowych</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="486"/>
        <source>Number of centerline features written.</source>
        <translation>Liczba zapisanych obiektów linii środkowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="491"/>
        <source>Number of skipped features</source>
        <translation>Liczba pominiętych obiektów</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="491"/>
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
        <location filename="../algorithms/running.py" line="108"/>
        <source>{} must be a {} layer, but &apos;{}&apos; holds {} geometries.</source>
        <translation>{} musi być warstwą typu {}, a '{}' zawiera geometrie typu {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="62"/>
        <source>the feature has no geometry</source>
        <translation>obiekt nie ma geometrii</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="202"/>
        <source>Feature {} skipped: {}</source>
        <translation>Obiekt {} pominięty: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="210"/>
        <source>Feature {}: {}</source>
        <translation>Obiekt {}: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="231"/>
        <source>{} (part {})</source>
        <translation>{} (część {})</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="257"/>
        <source>unexpected {}: {} (please report this with the feature)</source>
        <translation>nieoczekiwany błąd {}: {} (prosimy zgłosić go wraz z obiektem)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="426"/>
        <source>Write the incircle diameter (local width, layer units or metres) as M value of each vertex.</source>
        <translation>Zapisz średnicę okręgu wpisanego (lokalną szerokość, w jednostkach warstwy lub metrach) jako wartość M każdego wierzchołka.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="448"/>
        <source>Optional point layer: every centerline vertex with its chainage, incircle radius and width.</source>
        <translation>Opcjonalna warstwa punktowa: każdy wierzchołek linii środkowej z kilometrażem, promieniem okręgu wpisanego i szerokością.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="448"/>
        <source>Optional polygon layer: the incircle of every vertex, with its radius and chainage.</source>
        <translation>Opcjonalna warstwa poligonowa: okrąg wpisany każdego wierzchołka z promieniem i kilometrażem.</translation>
    </message>
    <message>
        <location filename="../algorithms/outputs.py" line="237"/>
        <source>Could not write a centerline: {}</source>
        <translation>Nie udało się zapisać linii środkowej: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="448"/>
        <source>Optional line layer: cross-sections from bank to bank through the centerline, one every &apos;Distance between transects&apos;, with their width and chainage.</source>
        <translation>Opcjonalna warstwa liniowa: przekroje poprzeczne od brzegu do brzegu przez linię środkową, jeden co 'Odległość między przekrojami', z szerokością i kilometrażem.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="337"/>
        <source>Largest deviation from the exact medial axis (0 = automatic)</source>
        <translation>Największe odchylenie od dokładnej osi środkowej (0 = automatycznie)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="350"/>
        <source>Fixed boundary sampling distance (0 = adaptive)</source>
        <translation>Stały odstęp próbkowania brzegu (0 = adaptacyjnie)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="350"/>
        <source>The paper&apos;s fixed sampling: a sample every this distance along both sides, in layer units (metres for a layer in degrees), giving many evenly spaced vertices. Use it to reproduce the paper or for a dense line; 0 uses the adaptive sampling bounded by the largest deviation. Give either this or the largest deviation, not both.</source>
        <translation>Stałe próbkowanie z artykułu: próbka co tę odległość wzdłuż obu stron, w jednostkach warstwy (metry dla warstwy w stopniach), dające wiele równomiernie rozmieszczonych wierzchołków. Do odtworzenia artykułu lub gęstej linii; 0 oznacza próbkowanie adaptacyjne ograniczone największym odchyleniem. Podaj to albo największe odchylenie, nie oba.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="376"/>
        <source>Give either a largest deviation from the axis (adaptive sampling) or a fixed boundary sampling distance, not both; set the other one to 0.</source>
        <translation>Podaj największe odchylenie od osi (próbkowanie adaptacyjne) albo stały odstęp próbkowania brzegu, nie oba; ustaw drugie na 0.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="395"/>
        <source>Split point snapping tolerance</source>
        <translation>Tolerancja przyciągania punktów podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="419"/>
        <source>Islands (holes)</source>
        <translation>Wyspy (otwory)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="418"/>
        <source>Pass through the main channel</source>
        <translation>Prowadź głównym korytem</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="418"/>
        <source>Ignore islands</source>
        <translation>Pomijaj wyspy</translation>
    </message>
    <message>
        <location filename="../algorithms/network_outputs.py" line="107"/>
        <source>Could not write a branch: {}</source>
        <translation>Nie można zapisać gałęzi: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/units.py" line="23"/>
        <source>layer units</source>
        <translation>jednostki warstwy</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="139"/>
        <source>{}: {} has no field &apos;{}&apos;; its fields are: {}.</source>
        <translation>{}: {} nie ma pola '{}'; jego pola to: {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="139"/>
        <source>none</source>
        <translation>brak</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="239"/>
        <source>Parameters</source>
        <translation>Parametry</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="239"/>
        <source>Advanced parameters</source>
        <translation>Parametry zaawansowane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="239"/>
        <source>Outputs</source>
        <translation>Wyniki</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="127"/>
        <source>Z values are ignored: &apos;{}&apos; has Z, but the centerline is computed in the plane and written without Z (its M values, when stored, are the local width).</source>
        <translation>Wartości Z są pomijane: '{}' ma współrzędną Z, ale linia środkowa jest obliczana na płaszczyźnie i zapisywana bez Z (jej wartości M, jeśli są zapisywane, to lokalna szerokość).</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="190"/>
        <source>centerlines</source>
        <translation>linie środkowe</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="204"/>
        <source>vertices</source>
        <translation>wierzchołki</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="205"/>
        <source>transects</source>
        <translation>przekroje</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="206"/>
        <source>incircles</source>
        <translation>okręgi wpisane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="209"/>
        <source>{layer} — {output} ({rule})</source>
        <translation>{layer} — {output} ({rule})</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="211"/>
        <source>{layer} — {output}</source>
        <translation>{layer} — {output}</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="337"/>
        <source>Every vertex is the centre of a circle touching both sides; the line of the centres of all such circles is the exact medial axis. This is the largest distance between the centerline and that axis, in layer units (metres for a layer in degrees): the line keeps only the vertices it needs to stay that close, each lying exactly on the axis, and never leaves the shape whatever the value. 0 uses 1/200 of the shape&apos;s typical width: the right choice for maps. It may differ per feature (data-defined).</source>
        <translation>Każdy wierzchołek jest środkiem okręgu stycznego do obu stron; linia środków wszystkich takich okręgów to dokładna oś środkowa. To największa odległość linii środkowej od tej osi, w jednostkach warstwy (metry dla warstwy w stopniach): linia zachowuje tylko wierzchołki potrzebne, by pozostać tak blisko, każdy leżący dokładnie na osi, i niezależnie od wartości nigdy nie wychodzi poza kształt. 0 oznacza 1/200 typowej szerokości kształtu: właściwy wybór dla map. Może być inna dla każdego obiektu (wartość definiowana danymi).</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="395"/>
        <source>Largest distance between a split point and the polygon&apos;s exterior ring, layer units (metres for a layer in degrees); 0 = a millionth of the polygon&apos;s size. It may differ per feature (data-defined).</source>
        <translation>Największa odległość punktu podziału od zewnętrznego pierścienia poligonu, w jednostkach warstwy (metry dla warstwy w stopniach); 0 = jedna milionowa rozmiaru poligonu. Może być inna dla każdego obiektu (wartość definiowana danymi).</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="476"/>
        <source>Distance along the centerline between two transects, layer units (metres for a layer in degrees); 0 uses the mean width of each centerline. It may differ per feature (data-defined).</source>
        <translation>Odległość wzdłuż linii środkowej między dwoma przekrojami, w jednostkach warstwy (metry dla warstwy w stopniach); 0 oznacza średnią szerokość każdej linii środkowej. Może być inna dla każdego obiektu (wartość definiowana danymi).</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="42"/>
        <source>metres</source>
        <translation>metry</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="43"/>
        <source>kilometres</source>
        <translation>kilometry</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="44"/>
        <source>feet</source>
        <translation>stopy</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="45"/>
        <source>yards</source>
        <translation>jardy</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="46"/>
        <source>miles</source>
        <translation>mile</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="47"/>
        <source>nautical miles</source>
        <translation>mile morskie</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="48"/>
        <source>centimetres</source>
        <translation>centymetry</translation>
    </message>
    <message>
        <location filename="../algorithms/length_widget.py" line="49"/>
        <source>millimetres</source>
        <translation>milimetry</translation>
    </message>
</context>
<context>
    <name>IncirCuCore</name>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="30"/>
        <source>polygon</source>
        <translation>poligon</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="31"/>
        <source>exterior ring</source>
        <translation>pierścień zewnętrzny</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="32"/>
        <source>pair of lines</source>
        <translation>para linii</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="33"/>
        <source>first line</source>
        <translation>pierwsza linia</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="34"/>
        <source>second line</source>
        <translation>druga linia</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="35"/>
        <source>first chain</source>
        <translation>pierwszy łańcuch</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="36"/>
        <source>second chain</source>
        <translation>drugi łańcuch</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="43"/>
        <source>split points</source>
        <translation>punkty podziału</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="38"/>
        <source>line</source>
        <translation>linia</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="39"/>
        <source>chain</source>
        <translation>łańcuch</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="40"/>
        <source>The polygon</source>
        <translation>Poligon</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="41"/>
        <source>The part</source>
        <translation>Część</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="42"/>
        <source>split point</source>
        <translation>punkt podziału</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="44"/>
        <source>it needs 2 (or none, to find its ends automatically)</source>
        <translation>potrzebne są 2 (albo żaden, by końce wyznaczyć automatycznie)</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="45"/>
        <source>a network needs at least 2</source>
        <translation>sieć potrzebuje co najmniej 2</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="47"/>
        <source>Unknown island mode {mode!r}; use one of {choices}.</source>
        <translation>Nieznany tryb wysp {mode!r}; użyj jednego z: {choices}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="48"/>
        <source>Unknown end rule {rule!r}; use one of {choices}.</source>
        <translation>Nieznana reguła końców {rule!r}; użyj jednej z: {choices}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="49"/>
        <source>{name} must be a number (a length in {units}), got {value!r}.</source>
        <translation>{name} musi być liczbą (długością w: {units}), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="52"/>
        <source>{name} must be a positive, finite length in {units} (or 0 for automatic), got {value!r}.</source>
        <translation>{name} musi być dodatnią, skończoną długością w: {units} (lub 0 = automatycznie), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="55"/>
        <source>{name} must be a non-negative, finite distance in {units} (or None), got {value!r}.</source>
        <translation>{name} musi być nieujemną, skończoną odległością w: {units} (lub None), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="58"/>
        <source>{name} must be a number, got {kind} {value!r}.</source>
        <translation>{name} musi być liczbą, podano {kind} {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="59"/>
        <source>samples_per_chain must be a whole number, got {value!r}.</source>
        <translation>samples_per_chain musi być liczbą całkowitą, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="60"/>
        <source>The number of samples per chain must be at least 1, got {value!r}.</source>
        <translation>Liczba próbek na łańcuch musi wynosić co najmniej 1, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="67"/>
        <source>Give either a tolerance (adaptive sampling) or a spacing / sample count (fixed sampling).</source>
        <translation>Podaj tolerancję (próbkowanie adaptacyjne) albo odstęp lub liczbę próbek (próbkowanie stałe), nie oba.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="75"/>
        <source>A circle needs at least 1 segment per quarter, got {value!r}.</source>
        <translation>Okrąg potrzebuje co najmniej 1 odcinka na ćwiartkę, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="78"/>
        <source>The transect interval must be a distance, got {value!r}.</source>
        <translation>Odstęp przekrojów musi być odległością, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="81"/>
        <source>The transect interval must be a positive distance, got {value!r}.</source>
        <translation>Odstęp przekrojów musi być dodatnią odległością, podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="84"/>
        <source>{guides} guides were given for {polygons} polygons.</source>
        <translation>Podano linii prowadzących: {guides}, a poligonów: {polygons}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="86"/>
        <source>The polygon is null (no geometry).</source>
        <translation>Poligon jest pusty (brak geometrii).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="87"/>
        <source>The polygon is empty.</source>
        <translation>Poligon jest pusty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="88"/>
        <source>Expected a polygon or multipolygon, got a {kind}.</source>
        <translation>Oczekiwano poligonu lub multipoligonu, podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="89"/>
        <source>Expected a single polygon, got a {kind}.</source>
        <translation>Oczekiwano pojedynczego poligonu, podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="90"/>
        <source>The polygon is not valid: {reason}. Repair it first (e.g. QGIS &apos;{fix_geometries}&apos;).</source>
        <translation>Poligon jest nieprawidłowy: {reason}. Najpierw go napraw (np. narzędziem QGIS „{fix_geometries}”).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="93"/>
        <source>The {name} is null (no geometry).</source>
        <translation>Obiekt „{name}” nie ma geometrii.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="94"/>
        <source>The {name} is empty.</source>
        <translation>Obiekt „{name}” jest pusty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="95"/>
        <source>The {name} must be a single line, not a {kind}.</source>
        <translation>Obiekt „{name}” musi być pojedynczą linią, a nie {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="96"/>
        <source>The {name} must be an (n, 2) array of numbers.</source>
        <translation>Obiekt „{name}” musi być tablicą liczb (n, 2).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="97"/>
        <source>The {name} must be an (n, 2) coordinate array.</source>
        <translation>Obiekt „{name}” musi być tablicą współrzędnych (n, 2).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="98"/>
        <source>The {name} has a NaN or infinite coordinate: {value}.</source>
        <translation>Obiekt „{name}” ma współrzędną NaN lub nieskończoną: {value}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="115"/>
        <source>The polygon&apos;s size ({size:.3g}) is absurd for its coordinates&apos; units; reproject or rescale it.</source>
        <translation>Rozmiar poligonu ({size:.3g}) jest niedorzeczny dla jednostek jego współrzędnych; przelicz go do innego układu lub przeskaluj.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="118"/>
        <source>The boundary has {count:,} segments, more than this engine can index.</source>
        <translation>Obrys ma {count:,} odcinków, więcej niż ten silnik może zindeksować.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="121"/>
        <source>A guide must be a line or multiline, got a {kind}.</source>
        <translation>Linia prowadząca musi być linią lub multilinią, podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="122"/>
        <source>The guide line has a NaN or infinite coordinate.</source>
        <translation>Linia prowadząca ma współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="123"/>
        <source>Island {index} is empty or has a NaN or infinite coordinate.</source>
        <translation>Wyspa {index} jest pusta lub ma współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="126"/>
        <source>Island {index} has fewer than 3 distinct points.</source>
        <translation>Wyspa {index} ma mniej niż 3 różne punkty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="127"/>
        <source>Cannot centre a projection on a null geometry.</source>
        <translation>Nie można wyśrodkować odwzorowania na braku geometrii.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="128"/>
        <source>Cannot centre a projection on an empty geometry.</source>
        <translation>Nie można wyśrodkować odwzorowania na pustej geometrii.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="129"/>
        <source>Cannot centre a projection on a geometry with a NaN or infinite coordinate.</source>
        <translation>Nie można wyśrodkować odwzorowania na geometrii ze współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="140"/>
        <source>Unknown CRS {crs!r}: {error}</source>
        <translation>Nieznany układ współrzędnych {crs!r}: {error}</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="141"/>
        <source>{name} is not a geographic CRS.</source>
        <translation>{name} nie jest układem geograficznym.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="143"/>
        <source>The {name} has fewer than 2 distinct points.</source>
        <translation>Obiekt „{name}” ma mniej niż 2 różne punkty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="144"/>
        <source>The {name} folds back over itself at {point}.</source>
        <translation>Obiekt „{name}” zawraca na sobie w punkcie {point}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="145"/>
        <source>The {name} crosses itself at {point}.</source>
        <translation>Obiekt „{name}” przecina sam siebie w punkcie {point}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="146"/>
        <source>The two lines cross or touch at {point}; they must bound a region between them.</source>
        <translation>Obie linie przecinają się lub stykają w punkcie {point}; muszą ograniczać obszar między sobą.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="149"/>
        <source>The two lines enclose no area between them (they lie on one line).</source>
        <translation>Obie linie nie ograniczają żadnego obszaru (leżą na jednej prostej).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="152"/>
        <source>The chains are too close together or too short to carry a centerline.</source>
        <translation>Łańcuchy są zbyt blisko siebie lub zbyt krótkie, by wyznaczyć linię środkową.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="178"/>
        <source>A polygon needs exactly 2 split points on its boundary, got {count}.</source>
        <translation>Poligon potrzebuje dokładnie 2 punktów podziału na obrysie, podano: {count}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="181"/>
        <source>Both split points snap to the same place {point} of the boundary.</source>
        <translation>Oba punkty podziału przyciągają się do tego samego miejsca {point} obrysu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="184"/>
        <source>Split points must be a sequence of two points (or a MultiPoint), got a {kind}.</source>
        <translation>Punkty podziału muszą być ciągiem dwóch punktów (lub multipunktem), podano {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="187"/>
        <source>Split point {index} is an empty point.</source>
        <translation>Punkt podziału {index} jest pusty.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="188"/>
        <source>Split point {index} must be a point, not a {kind}.</source>
        <translation>Punkt podziału {index} musi być punktem, a nie {kind}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="193"/>
        <source>Split point {index} must be an (x, y) pair of numbers, got {value!r}.</source>
        <translation>Punkt podziału {index} musi być parą liczb (x, y), podano {value!r}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="196"/>
        <source>A split point has a NaN or infinite coordinate.</source>
        <translation>Punkt podziału ma współrzędną NaN lub nieskończoną.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="201"/>
        <source>The ends of the polygon cannot be found: {error}.</source>
        <translation>Nie można wyznaczyć końców poligonu: {error}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="202"/>
        <source>The polygon is too thin or too small to find its ends automatically.</source>
        <translation>Poligon jest zbyt cienki lub zbyt mały, by automatycznie wyznaczyć jego końce.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="205"/>
        <source>The polygon&apos;s outline could not be triangulated to find its ends automatically.</source>
        <translation>Nie udało się striangulować obrysu poligonu, by automatycznie wyznaczyć jego końce.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="208"/>
        <source>The guide line does not come near the polygon; its ends were found automatically.</source>
        <translation>Linia prowadząca nie przebiega w pobliżu poligonu; jego końce wyznaczono automatycznie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="211"/>
        <source>The shape is not elongated; its automatically found ends are arbitrary.</source>
        <translation>Kształt nie jest wydłużony; jego automatycznie wyznaczone końce są przypadkowe.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="221"/>
        <source>The computed centerline has a NaN or infinite coordinate; none is returned.</source>
        <translation>Obliczona linia środkowa ma współrzędną NaN lub nieskończoną; nie zwrócono jej.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="242"/>
        <source>A network needs at least 2 split points on the boundary, got {count}.</source>
        <translation>Sieć potrzebuje co najmniej 2 punktów podziału na obrysie, podano: {count}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="245"/>
        <source>Two split points snap to the same place {point} of the boundary.</source>
        <translation>Dwa punkty podziału przyciągają się do tego samego miejsca {point} obrysu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="248"/>
        <source>The split points could not be placed in order on the boundary with its islands.</source>
        <translation>Nie udało się uporządkować punktów podziału na obrysie z jego wyspami.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="261"/>
        <source>A branch of the network has fewer than 2 vertices; try a smaller spacing.</source>
        <translation>Gałąź sieci ma mniej niż 2 wierzchołki; spróbuj mniejszego odstępu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="63"/>
        <source>A spacing of {spacing:.6g} would need about {planned:.3g} samples (at most {limit:.3g}); use a larger spacing.</source>
        <translation>Odstęp {spacing:.6g} wymagałby około {planned:.3g} próbek (najwyżej {limit:.3g}); użyj większego odstępu.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="70"/>
        <source>The tolerance {tolerance:.6g} is below {relative:g} of the shape&apos;s extent ({extent:.6g}): float64 cannot place vertices that finely. Use at least {least:.6g} ({units}), or 0 for the automatic tolerance.</source>
        <translation>Tolerancja {tolerance:.6g} jest mniejsza niż {relative:g} rozmiaru kształtu ({extent:.6g}): float64 nie umieści wierzchołków tak dokładnie. Użyj co najmniej {least:.6g} ({units}) albo 0, by tolerancję dobrać automatycznie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="99"/>
        <source>The {name} has a coordinate of magnitude {magnitude:.3g}, beyond {limit:.0e}: products of such coordinates overflow float64. Use a projected CRS in metres, or scale the data down.</source>
        <translation>Obiekt „{name}” ma współrzędną rzędu {magnitude:.3g}, powyżej {limit:.0e}: iloczyny takich współrzędnych przekraczają zakres float64. Użyj odwzorowanego układu w metrach albo zmniejsz skalę danych.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="104"/>
        <source>The {name} is {extent:.3g} across, under {limit:.0e}: products of its lengths underflow float64. Scale the data up (use smaller units).</source>
        <translation>Obiekt „{name}” ma rozmiar {extent:.3g}, poniżej {limit:.0e}: iloczyny jego długości wychodzą poza zakres float64. Powiększ skalę danych (użyj mniejszych jednostek).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="109"/>
        <source>The {name} is {extent:.3g} across at coordinates of magnitude {magnitude:.3g}: float64 cannot resolve a shape smaller than {limit:.0e} of its distance from the origin. Shift the data nearer the origin (subtract an offset) or use a local projected CRS.</source>
        <translation>Obiekt „{name}” ma rozmiar {extent:.3g} przy współrzędnych rzędu {magnitude:.3g}: float64 nie rozróżni kształtu mniejszego niż {limit:.0e} jego odległości od początku układu. Przesuń dane bliżej początku układu (odejmij przesunięcie) albo użyj lokalnego układu odwzorowanego.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="132"/>
        <source>The projection centre ({longitude!r}, {latitude!r}) is not a longitude and a latitude in degrees.</source>
        <translation>Środek odwzorowania ({longitude!r}, {latitude!r}) nie jest długością i szerokością geograficzną w stopniach.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="136"/>
        <source>A point could not be projected (a NaN or infinite coordinate, or a latitude beyond 90 degrees).</source>
        <translation>Nie udało się przeliczyć punktu (współrzędna NaN lub nieskończona albo szerokość geograficzna ponad 90 stopni).</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="155"/>
        <source>The first line is {length:.6g} long, {ratio:.3g} times the second one ({other:.6g} {units}): it runs on beyond the other, where the region between them is closed by the straight gap between their ends, and the centerline follows that gap there. Cut the lines to where they face each other.</source>
        <translation>Pierwsza linia ma długość {length:.6g}, {ratio:.3g} razy więcej niż druga ({other:.6g} {units}): biegnie dalej niż druga, tam obszar między nimi zamyka prosty odcinek między ich końcami, a linia środkowa biegnie wzdłuż niego. Przytnij linie do odcinków leżących naprzeciw siebie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="161"/>
        <source>The second line is {length:.6g} long, {ratio:.3g} times the first one ({other:.6g} {units}): it runs on beyond the other, where the region between them is closed by the straight gap between their ends, and the centerline follows that gap there. Cut the lines to where they face each other.</source>
        <translation>Druga linia ma długość {length:.6g}, {ratio:.3g} razy więcej niż pierwsza ({other:.6g} {units}): biegnie dalej niż pierwsza, tam obszar między nimi zamyka prosty odcinek między ich końcami, a linia środkowa biegnie wzdłuż niego. Przytnij linie do odcinków leżących naprzeciw siebie.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="168"/>
        <source>Split point {point} is {distance:.6g} {units} away from the polygon&apos;s boundary; the snap tolerance is {tolerance:.6g} {units}. Move the point onto the boundary or raise the tolerance.</source>
        <translation>Punkt podziału {point} leży {distance:.6g} {units} od obrysu poligonu; tolerancja przyciągania wynosi {tolerance:.6g} {units}. Przesuń punkt na obrys albo zwiększ tolerancję.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="173"/>
        <source>{subject} has {count} {points} within the snap tolerance ({tolerance:.6g} {units}) of its exterior ring; {needed}.</source>
        <translation>{subject}: liczba punktów podziału w granicach tolerancji przyciągania ({tolerance:.6g} {units}) od pierścienia zewnętrznego wynosi {count}; {needed}.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="189"/>
        <source>Split point {index} is the number {value!r}: give a sequence of points, such as [(x1, y1), (x2, y2)].</source>
        <translation>Punkt podziału {index} jest liczbą {value!r}: podaj ciąg punktów, np. [(x1, y1), (x2, y2)].</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="197"/>
        <source>The ends found automatically coincide at {point}: the shape has no clear ends. Give two split points.</source>
        <translation>Automatycznie wyznaczone końce pokrywają się w punkcie {point}: kształt nie ma wyraźnych końców. Podaj dwa punkty podziału.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="215"/>
        <source>The island at {point} cannot be joined to a bank without crossing another island; use the option to ignore islands.</source>
        <translation>Wyspy w punkcie {point} nie da się połączyć z brzegiem bez przecięcia innej wyspy; użyj opcji pomijania wysp.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="224"/>
        <source>The computed centerline crosses itself, so none is returned. This happens where the shape has no single axis near the ends (a compact shape, or a split point in a corner): move the split points to the middle of the ends, or change the spacing.</source>
        <translation>Obliczona linia środkowa przecina samą siebie, więc jej nie zwrócono. Dzieje się tak, gdy kształt nie ma jednej osi przy końcach (zwarty kształt lub punkt podziału w narożniku): przesuń punkty podziału na środek końców albo zmień odstęp.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="230"/>
        <source>The computed centerline crosses itself at {point}, so none is returned. This happens where the shape has no single axis near the ends (a compact shape, or a split point in a corner): move the split points to the middle of the ends, or change the spacing.</source>
        <translation>Obliczona linia środkowa przecina samą siebie w punkcie {point}, więc jej nie zwrócono. Dzieje się tak, gdy kształt nie ma jednej osi przy końcach (zwarty kształt lub punkt podziału w narożniku): przesuń punkty podziału na środek końców albo zmień odstęp.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="236"/>
        <source>The computed centerline leaves the polygon at {point} ({outside:.6g} outside), so none is returned. Give split points, or change the tolerance.</source>
        <translation>Obliczona linia środkowa wychodzi poza poligon w punkcie {point} (o {outside:.6g}), więc jej nie zwrócono. Podaj punkty podziału albo zmień tolerancję.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="251"/>
        <source>The junction near {point} could not be located: its circle holds another chain out of order. Move the split points farther out along the arms.</source>
        <translation>Nie udało się wyznaczyć węzła w pobliżu punktu {point}: jego okrąg obejmuje inny łańcuch poza kolejnością. Przesuń punkty podziału dalej wzdłuż ramion.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="256"/>
        <source>The junction near {point} could not be located: its circle touches a chain at several places or a split point itself. Move the split points farther out along the arms.</source>
        <translation>Nie udało się wyznaczyć węzła w pobliżu punktu {point}: jego okrąg dotyka łańcucha w kilku miejscach lub samego punktu podziału. Przesuń punkty podziału dalej wzdłuż ramion.</translation>
    </message>
    <message>
        <location filename="../incircu_plugin/core/errors.py" line="264"/>
        <source>The network found is not a tree with one end at each of the {k} split points ({branches} branches, {ends} ends, {weak} junctions of degree below 3); a split point may lie on a junction&apos;s circle: move the split points farther out along the arms.</source>
        <translation>Wyznaczona sieć nie jest drzewem z jednym końcem w każdym z {k} punktów podziału (gałęzie: {branches}, końce: {ends}, węzły stopnia mniejszego niż 3: {weak}); punkt podziału może leżeć na okręgu węzła: przesuń punkty podziału dalej wzdłuż ramion.</translation>
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
        <location filename="../algorithms/lines_centerline.py" line="89"/>
        <source>Pairing field of the second lines</source>
        <translation>Pole parujące drugich linii</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="139"/>
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
        <location filename="../algorithms/lines_centerline.py" line="72"/>
        <source>Line layer of the other side; reprojected to the CRS of the first lines when needed.</source>
        <translation>Warstwa liniowa drugiej strony; w razie potrzeby przeliczana do układu pierwszych linii.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="89"/>
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
        <location filename="../algorithms/lines_centerline.py" line="124"/>
        <source>Give both {} and {}, or neither (then each layer holds one line).</source>
        <translation>Podaj oba pola, {} i {}, albo żadnego (wtedy każda warstwa zawiera jedną linię).</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="142"/>
        <source>{} holds {} separate lines that do not join into one; give {} and {} to pair them, or merge them into one line.</source>
        <translation>{} zawiera linie, które nie łączą się w jedną (jest ich {}); podaj {} i {}, aby je sparować, albo scal je w jedną linię.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="161"/>
        <source>No line in {} has {} = {!r}; line {} of {} unused.</source>
        <translation>Żadna linia w {} nie ma {} = {!r}; linia {} z {} nie została użyta.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="172"/>
        <source>no line in {} has {} = {!r}</source>
        <translation>żadna linia w {} nie ma {} = {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="190"/>
        <source>the lines of {} with this pairing value do not join into one</source>
        <translation>linie z {} o tej wartości parowania nie łączą się w jedną</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="54"/>
        <source>Computes one unbranched centerline between two lines (for example the two banks of a river) with the Curve of Incircles: every vertex is the centre of a circle touching both lines. Lines are paired by equal values of the two pairing fields (or of a field both layers have); without them each layer holds one line (its features and parts are merged). The lines must not cross. The M value of each vertex is the local width. The second lines are reprojected to the CRS of the first; geographic layers are computed in a local metric projection and distances are then in metres.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową między dwiema liniami (na przykład dwoma brzegami rzeki) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu linii. Linie są łączone w pary według równych wartości obu pól parowania (lub pola, które mają obie warstwy); bez nich każda warstwa zawiera jedną linię (jej obiekty i części są scalane). Linie nie mogą się przecinać. Wartość M każdego wierzchołka to lokalna szerokość. Drugie linie są przeliczane do układu pierwszych; warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym i odległości są wtedy w metrach.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="76"/>
        <source>Optional; a line of the first lines is paired with the line of the second lines that has the same value in &apos;Pairing field of the second lines&apos;. Left empty, a field both layers have with values found in both pairs them (the log names it).</source>
        <translation>Opcjonalne; linia z pierwszych linii jest łączona w parę z linią z drugich linii o tej samej wartości w 'Pole parowania drugich linii'. Gdy puste, pary tworzy pole, które mają obie warstwy, o wartościach występujących w obu (dziennik je podaje).</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="117"/>
        <source>No pairing fields given: both layers have the field &apos;{}&apos;, so lines are paired by its values (give {} and {} to pair them otherwise).</source>
        <translation>Nie podano pól parowania: obie warstwy mają pole '{}', więc linie są łączone w pary według jego wartości (podaj {} i {}, by łączyć je inaczej).</translation>
    </message>
</context>
<context>
    <name>PolygonCenterlineAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="55"/>
        <source>centerline,centreline,medial axis,skeleton,river,road,dike,width,incircle</source>
        <translation>linia środkowa,oś,oś medialna,szkielet,rzeka,droga,wał,szerokość,okrąg wpisany</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="70"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="79"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="125"/>
        <source>One feature per polygon part</source>
        <translation>Jeden obiekt na każdą część poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="125"/>
        <source>Write one line feature per part of a multipart polygon instead of one MultiLineString per input feature.</source>
        <translation>Zapisz osobny obiekt liniowy dla każdej części poligonu wieloczęściowego zamiast jednego MultiLineString na obiekt wejściowy.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="38"/>
        <source>Centerline of polygons</source>
        <translation>Linia środkowa poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="41"/>
        <source>One unbranched centerline through each elongated polygon (river, road, dike).</source>
        <translation>Jedna nierozgałęziona linia środkowa każdego wydłużonego poligonu (rzeki, drogi, wału).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="44"/>
        <source>Centerlines of polygons</source>
        <translation>Linie środkowe poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="58"/>
        <source>Computes one unbranched, loop-free centerline for each polygon (each part of a multipart polygon) with the Curve of Incircles: every vertex is the centre of a circle touching both sides of the outline. The line runs between the two &apos;Split points&apos; lying on the polygon&apos;s outline, or, without them, between automatic ends: those of the internal path along the &apos;Guide lines&apos;, else of the main stem (or the longest internal path, see &apos;Automatic ends&apos;). Islands (holes) are passed on the side of the wider channel, or ignored. The M value of each vertex is the local width. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową bez pętli dla każdego poligonu (każdej części poligonu wieloczęściowego) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu stron obrysu. Linia biegnie między dwoma 'Punktami podziału' leżącymi na obrysie poligonu, a bez nich między końcami automatycznymi: końcami drogi wewnątrz kształtu wzdłuż 'Linii prowadzących', a bez nich głównego nurtu (lub najdłuższej drogi wewnątrz kształtu, zob. 'Końce automatyczne'). Wyspy (otwory) są omijane od strony szerszego koryta albo pomijane. Wartość M każdego wierzchołka to lokalna szerokość. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie da się przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="79"/>
        <source>Points marking where each centerline starts and ends: two per polygon part, within &apos;Split point snapping tolerance&apos; of its exterior ring. A part with none gets automatic ends; a part with one or more than two is skipped. Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Punkty wyznaczające początek i koniec każdej linii środkowej: dwa na część poligonu, w odległości do 'Tolerancja przyciągania punktów podziału' od jej zewnętrznego obrysu. Część bez punktów dostaje automatycznie wyznaczone końce; część z jednym lub więcej niż dwoma punktami jest pomijana. Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="102"/>
        <source>Automatic ends</source>
        <translation>Końce automatyczne</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="101"/>
        <source>Main stem (widest path)</source>
        <translation>Główny nurt (najszersza droga)</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="101"/>
        <source>Longest path</source>
        <translation>Najdłuższa droga</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="112"/>
        <source>Guide lines</source>
        <translation>Linie prowadzące</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="112"/>
        <source>Rough river lines (a national network, OpenStreetMap waterways) for polygons without split points: the ends are those of the internal path that best covers the guide lines near the polygon. Gaps, offsets, generalised pieces and tributaries are fine. Another CRS is reprojected.</source>
        <translation>Przybliżone linie rzek (sieć krajowa, cieki OpenStreetMap) dla poligonów bez punktów podziału: końcami są końce drogi wewnątrz kształtu, która najlepiej pokrywa linie prowadzące w pobliżu poligonu. Przerwy, przesunięcia, uogólnione fragmenty i dopływy nie przeszkadzają. Inny układ współrzędnych jest przeliczany.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="47"/>
        <source>Line layer: input attributes plus source_fid (the polygon&apos;s feature id, to join the line back to it), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees), n_vertices, ends_found (true when no split points were used) and ends_from (split_points, guide or automatic).</source>
        <translation>Warstwa liniowa: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia z nim linii), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach), n_vertices, ends_found (prawda, gdy nie użyto punktów podziału) i ends_from (split_points, guide lub automatic).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="70"/>
        <source>Elongated polygons (rivers, roads, dikes); multipart polygons get one centerline per part. Z values are ignored: the centerline is computed in the plane.</source>
        <translation>Wydłużone poligony (rzeki, drogi, wały); poligony wieloczęściowe dostają jedną linię środkową na część. Wartości Z są pomijane: linia środkowa jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="94"/>
        <source>{pass_through}: the line never crosses an island and goes round it on the side of the wider channel. {ignore}: holes are filled before computing.</source>
        <translation>{pass_through}: linia nigdy nie przecina wyspy i omija ją od strony szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="102"/>
        <source>For polygons without split points. {main_stem}: the internal path that sweeps the largest channel area (length times width), so a wide main river wins over a longer but narrow side arm. {longest_path}: the tips of the two longest arms.</source>
        <translation>Dla poligonów bez punktów podziału. {main_stem}: droga wewnątrz kształtu obejmująca największą powierzchnię koryta (długość razy szerokość), więc szeroka rzeka główna wygrywa z dłuższą, lecz wąską odnogą. {longest_path}: końce dwóch najdłuższych ramion.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="245"/>
        <source>0: a millionth of the polygon&apos;s size</source>
        <translation>0: jedna milionowa rozmiaru poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="224"/>
        <source>{} Its ends were found automatically.</source>
        <translation>{} Jego końce wyznaczono automatycznie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="247"/>
        <source>{} holds no point.</source>
        <translation>{} nie zawiera żadnego punktu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="248"/>
        <source>no split point lies within {} of its outline, the {}; the nearest is {:.6g} {} away.</source>
        <translation>żaden punkt podziału nie leży w odległości {} od jego obrysu, czyli w granicach {}; najbliższy jest w odległości {:.6g} {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="137"/>
        <source>split points</source>
        <translation>punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="139"/>
        <source>guide lines</source>
        <translation>linie prowadzące</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="140"/>
        <source>main stem</source>
        <translation>główny nurt</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="140"/>
        <source>longest path</source>
        <translation>najdłuższa droga</translation>
    </message>
</context>
<context>
    <name>PolygonNetworkAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_network.py" line="31"/>
        <source>Centerline network of polygons</source>
        <translation>Sieć linii środkowych poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="34"/>
        <source>The medial-axis tree between the arm ends of a confluence, a delta or a road junction.</source>
        <translation>Drzewo osi środkowej między końcami ramion zlewiska, delty lub skrzyżowania dróg.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="41"/>
        <source>Network branches</source>
        <translation>Gałęzie sieci</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="44"/>
        <source>network,confluence,delta,junction,crossing,medial axis,skeleton,river,road,width</source>
        <translation>sieć,zlewisko,delta,węzeł,skrzyżowanie,oś środkowa,szkielet,rzeka,droga,szerokość</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="63"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="72"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="72"/>
        <source>The ends of the network: at least two per polygon part, within &apos;Split point snapping tolerance&apos; of its exterior ring, typically one across each arm&apos;s end. A part with fewer is skipped. Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Końce sieci: co najmniej dwa na część poligonu, w granicach 'Tolerancji przyciągania punktów podziału' od jego pierścienia zewnętrznego, zwykle jeden w poprzek końca każdego ramienia. Część z mniejszą liczbą jest pomijana. Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="82"/>
        <source>Split point id field</source>
        <translation>Pole identyfikatora punktu podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="82"/>
        <source>Attribute naming each split point in from_point, to_point and the chains; default: its feature id.</source>
        <translation>Atrybut nazywający każdy punkt podziału w from_point, to_point i łańcuchach; domyślnie: identyfikator obiektu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="116"/>
        <source>Number of branches</source>
        <translation>Liczba gałęzi</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="116"/>
        <source>Number of branch features written.</source>
        <translation>Liczba zapisanych obiektów gałęzi.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="63"/>
        <source>Polygons with several arms (confluences, deltas, road junctions); each part gets its network. Z values are ignored: the network is computed in the plane.</source>
        <translation>Poligony z kilkoma ramionami (zlewiska, delty, skrzyżowania dróg); każda część dostaje swoją sieć. Wartości Z są pomijane: sieć jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="95"/>
        <source>{pass_through}: no branch crosses an island; each island belongs to the chain it is nearer to, so the branches go round it on the side of the wider channel. {ignore}: holes are filled before computing.</source>
        <translation>{pass_through}: żadna gałąź nie przecina wyspy; każda wyspa należy do bliższego łańcucha, więc gałęzie omijają ją od strony szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="104"/>
        <source>Line layer, one feature per branch: input attributes plus source_fid (the polygon&apos;s feature id, to join the branch back to it), from_point, to_point (split point ids or &apos;junction&apos;), right_chain, left_chain (each chain named &apos;a-b&apos; after the split points at its ends, counter-clockwise), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices.</source>
        <translation>Warstwa liniowa, jeden obiekt na gałąź: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia z nim gałęzi), from_point, to_point (identyfikatory punktów podziału lub 'junction'), right_chain, left_chain (każdy łańcuch nazwany 'a-b' od punktów podziału na jego końcach, przeciwnie do ruchu wskazówek zegara), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach) i n_vertices.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="37"/>
        <source>centerline network</source>
        <translation>sieć linii środkowych</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="47"/>
        <source>Computes, for each polygon (each part of a multipart polygon) with two or more &apos;Split points&apos; on its outline (the ends of the arms of a confluence, a delta or a road junction), lines down the middle of its arms, joined where the arms meet. The split points cut the outline into pieces, the chains, one between each two neighbouring points; each line runs through the centres of circles touching two chains, a path of the shape&apos;s medial axis (the line of the centres of all circles touching two sides): a tree with one end at each split point and junctions where a circle touches three chains, without side branches. Each branch is one line feature with the ids of the split points at its ends (&apos;junction&apos; at a junction), the chains on its right and left, its length and widths; the M value of each vertex is the local width. Two split points give exactly the polygon centerline. Islands (holes) are passed on the side of the wider channel, or ignored. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Wyznacza, dla każdego poligonu (każdej części poligonu wieloczęściowego) z dwoma lub więcej 'Punktami podziału' na obrysie (końcami ramion zlewiska, delty lub skrzyżowania dróg), linie biegnące środkiem jego ramion, połączone tam, gdzie ramiona się spotykają. Punkty podziału dzielą obrys na kawałki, łańcuchy, po jednym między każdymi dwoma sąsiednimi punktami; każda linia biegnie przez środki okręgów stycznych do dwóch łańcuchów, drogą osi środkowej kształtu (linii środków wszystkich okręgów stycznych do dwóch stron): drzewo z jednym końcem w każdym punkcie podziału i węzłami tam, gdzie okrąg dotyka trzech łańcuchów, bez bocznych odgałęzień. Każda gałąź to jeden obiekt liniowy z identyfikatorami punktów podziału na jej końcach ('junction' w węźle), łańcuchami po prawej i lewej, długością i szerokościami; wartość M każdego wierzchołka to lokalna szerokość. Dwa punkty podziału dają dokładnie linię środkową poligonu. Wyspy (otwory) są omijane od strony szerszego koryta albo pomijane. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie da się przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
</context>
</TS>
